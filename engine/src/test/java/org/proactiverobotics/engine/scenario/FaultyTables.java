package org.proactiverobotics.engine.scenario;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.Station;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * The robot tables with a fault to inject: while a scenario's package is set as failing, every
 * call made from a class of that package throws (as a database that refuses one scenario's
 * statements would); every other call goes through. Which scenario calls is read off the stack.
 */
final class FaultyTables implements SensorReadings, SensorRequests, MissionTables, StrategyTable, EngineComments {

    private static final StackWalker STACK = StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE);

    private final JdbcRobotTables tables;
    private volatile String failingPackage;

    FaultyTables(JdbcRobotTables tables) {
        this.tables = tables;
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
    public Optional<GpsFix> newestGps() {
        check();
        return tables.newestGps();
    }

    @Override
    public Optional<Heading> newestHeading() {
        check();
        return tables.newestHeading();
    }

    @Override
    public Optional<DistanceScan> newestScan() {
        check();
        return tables.newestScan();
    }

    @Override
    public Optional<BatteryState> newestBattery() {
        check();
        return tables.newestBattery();
    }

    @Override
    public long newestSimTimeMs(Sensor sensor) {
        check();
        return tables.newestSimTimeMs(sensor);
    }

    @Override
    public boolean pending(Sensor sensor) {
        check();
        if (sensor == failOnceOn) {
            failOnceOn = null;
            throw new IllegalStateException("injected fault: one read of " + sensor + " requests refused");
        }
        return tables.pending(sensor);
    }

    @Override
    public void request(Sensor sensor, long iteration) {
        check();
        tables.request(sensor, iteration);
    }

    @Override
    public List<Checkpoint> checkpoints() {
        check();
        return tables.checkpoints();
    }

    @Override
    public void markReached(int seq, long simTimeMs) {
        check();
        tables.markReached(seq, simTimeMs);
    }

    @Override
    public Optional<Station> rechargeStation() {
        check();
        return tables.rechargeStation();
    }

    @Override
    public OptionalDouble rechargeLevelPct() {
        check();
        return tables.rechargeLevelPct();
    }

    @Override
    public List<Entry> read() {
        check();
        return tables.read();
    }

    @Override
    public void write(List<Entry> entries) {
        tables.write(entries);
    }

    @Override
    public void send(long iteration, long simTimeMs, String scenario, String command) {
        check();
        tables.send(iteration, simTimeMs, scenario, command);
    }
}
