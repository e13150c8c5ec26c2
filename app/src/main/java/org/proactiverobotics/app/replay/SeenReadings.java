package org.proactiverobotics.app.replay;

import java.util.Optional;
import java.util.function.Consumer;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.WheelOdometry;

/**
 * The engine's sensor readings, passed through unchanged, remembering the newest of each the
 * engine's rules were given: what the engine saw, for the trace. Engine thread only.
 */
public final class SeenReadings implements SensorReadings {

    private final SensorReadings readings;
    private GpsFix gps;
    private Heading heading;
    private DistanceScan scan;
    private BatteryState battery;

    private SeenReadings(SensorReadings readings) {
        this.readings = readings;
    }

    /**
     * @param tables the engine's tables
     * @param sink   receives the recorder
     * @return the same tables, their readings recorded
     */
    public static EngineTables wrap(EngineTables tables, Consumer<SeenReadings> sink) {
        SeenReadings seen = new SeenReadings(tables.readings());
        sink.accept(seen);
        return new EngineTables(seen, tables.requests(), tables.mission(), tables.strategy(), tables.comments(),
                tables.pruneHistory(), tables.poses());
    }

    @Override
    public Optional<GpsFix> newestGps() {
        Optional<GpsFix> r = readings.newestGps();
        r.ifPresent(v -> gps = v);
        return r;
    }

    @Override
    public Optional<Heading> newestHeading() {
        Optional<Heading> r = readings.newestHeading();
        r.ifPresent(v -> heading = v);
        return r;
    }

    @Override
    public Optional<DistanceScan> newestScan() {
        Optional<DistanceScan> r = readings.newestScan();
        r.ifPresent(v -> scan = v);
        return r;
    }

    @Override
    public Optional<BatteryState> newestBattery() {
        Optional<BatteryState> r = readings.newestBattery();
        r.ifPresent(v -> battery = v);
        return r;
    }

    /** Passed through, not remembered: the trace has no odometry (yet). */
    @Override
    public Optional<WheelOdometry> newestOdometry() {
        return readings.newestOdometry();
    }

    @Override
    public long newestSimTimeMs(Sensor sensor) {
        return readings.newestSimTimeMs(sensor);
    }

    /** @return the newest GPS reading the engine was given, or null */
    public GpsFix gps() {
        return gps;
    }

    /** @return the newest heading the engine was given, or null */
    public Heading heading() {
        return heading;
    }

    /** @return the newest distance scan the engine was given, or null */
    public DistanceScan scan() {
        return scan;
    }

    /** @return the newest battery reading the engine was given, or null */
    public BatteryState battery() {
        return battery;
    }
}
