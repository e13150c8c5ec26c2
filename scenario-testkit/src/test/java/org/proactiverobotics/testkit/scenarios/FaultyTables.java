package org.proactiverobotics.testkit.scenarios;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.WheelOdometry;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.Station;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * The robot tables with a fault to inject: while a scenario's package is set as failing, every
 * call made from a class of that package throws (as a database that refuses one scenario's
 * statements would); every other call goes through. Which scenario calls is read off the stack.
 * Give {@link #wrap} to the kit's {@code faults}.
 */
final class FaultyTables implements SensorReadings, SensorRequests, MissionTables, StrategyTable, EngineComments,
        PoseEstimateTable {

    private static final StackWalker STACK = StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE);

    private EngineTables tables;
    private volatile String failingPackage;

    /** @return the tables the engine's rules see: these, calling through to the given ones */
    EngineTables wrap(EngineTables wrapped) {
        this.tables = wrapped;
        return new EngineTables(this, this, this, this, this, wrapped.pruneHistory(), this);
    }

    /** Every call from this scenario's package throws from now on. */
    void fail(Class<?> scenarioClass) {
        failingPackage = scenarioClass.getPackageName();
    }

    /** The fault is gone. */
    void heal() {
        failingPackage = null;
    }

    private volatile Sensor failOnceOn;

    /** The next pending() for this sensor throws, once (a brief fault in one data-acquisition rule). */
    void failOnce(Sensor sensor) {
        failOnceOn = sensor;
    }

    private void check() {
        String p = failingPackage;
        if (p != null && STACK.walk(frames -> frames.anyMatch(f -> f.getDeclaringClass().getPackageName().equals(p)))) {
            throw new IllegalStateException("injected fault: the database refuses " + p);
        }
    }

    @Override
    public Optional<PoseEstimate> newestPose() {
        check();
        return tables.poses().newestPose();
    }

    @Override
    public void writePose(PoseEstimate estimate) {
        check();
        tables.poses().writePose(estimate);
    }

    @Override
    public Optional<GpsFix> newestGps() {
        check();
        return tables.readings().newestGps();
    }

    @Override
    public Optional<Heading> newestHeading() {
        check();
        return tables.readings().newestHeading();
    }

    @Override
    public Optional<DistanceScan> newestScan() {
        check();
        return tables.readings().newestScan();
    }

    @Override
    public Optional<BatteryState> newestBattery() {
        check();
        return tables.readings().newestBattery();
    }

    @Override
    public Optional<WheelOdometry> newestOdometry() {
        check();
        return tables.readings().newestOdometry();
    }

    @Override
    public long newestSimTimeMs(Sensor sensor) {
        check();
        return tables.readings().newestSimTimeMs(sensor);
    }

    @Override
    public boolean pending(Sensor sensor) {
        check();
        if (sensor == failOnceOn) {
            failOnceOn = null;
            throw new IllegalStateException("injected fault: one read of " + sensor + " requests refused");
        }
        return tables.requests().pending(sensor);
    }

    @Override
    public void request(Sensor sensor, long iteration) {
        check();
        tables.requests().request(sensor, iteration);
    }

    @Override
    public List<Checkpoint> checkpoints() {
        check();
        return tables.mission().checkpoints();
    }

    @Override
    public void markReached(int seq, long simTimeMs) {
        check();
        tables.mission().markReached(seq, simTimeMs);
    }

    @Override
    public Optional<Station> rechargeStation() {
        check();
        return tables.mission().rechargeStation();
    }

    @Override
    public OptionalDouble rechargeLevelPct() {
        check();
        return tables.mission().rechargeLevelPct();
    }

    @Override
    public List<Entry> read() {
        check();
        return tables.strategy().read();
    }

    @Override
    public void write(List<Entry> entries) {
        tables.strategy().write(entries);
    }

    @Override
    public void send(long iteration, long simTimeMs, String scenario, String command) {
        check();
        tables.comments().send(iteration, simTimeMs, scenario, command);
    }
}
