package org.proactiverobotics.testkit;

import java.util.Optional;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.WheelOdometry;

/** The readings with a fault to inject: while on, reading the newest scan throws. */
final class ScanFault implements SensorReadings {

    private SensorReadings readings;
    private boolean on;

    /** Give this to {@link ScenarioKit.Builder#faults}: the tables, reading through this fault. */
    EngineTables wrap(EngineTables tables) {
        readings = tables.readings();
        return new EngineTables(this, tables.requests(), tables.mission(), tables.strategy(), tables.comments(),
                tables.pruneHistory(), tables.poses());
    }

    void on() {
        on = true;
    }

    void off() {
        on = false;
    }

    @Override
    public Optional<DistanceScan> newestScan() {
        if (on) {
            throw new IllegalStateException("injected fault: the scan cannot be read");
        }
        return readings.newestScan();
    }

    @Override
    public Optional<GpsFix> newestGps() {
        return readings.newestGps();
    }

    @Override
    public Optional<Heading> newestHeading() {
        return readings.newestHeading();
    }

    @Override
    public Optional<BatteryState> newestBattery() {
        return readings.newestBattery();
    }

    @Override
    public Optional<WheelOdometry> newestOdometry() {
        return readings.newestOdometry();
    }

    @Override
    public long newestSimTimeMs(Sensor sensor) {
        return readings.newestSimTimeMs(sensor);
    }
}
