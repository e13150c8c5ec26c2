package org.proactiverobotics.engine.scenario.dataacquisition;

import org.proactiverobotics.engine.tables.Sensor;

/** Keeps a recent reading of the robot's position in the database (default interval 0 ms: every iteration). */
public final class GetGPS extends SensorWatch {

    /** The default interval, simulated milliseconds. */
    public static final long DEFAULT_INTERVAL_MS = 0;

    /** A watch with the default interval. */
    public GetGPS() {
        this(DEFAULT_INTERVAL_MS);
    }

    /** @param intervalMs how old the newest reading may be, simulated milliseconds */
    public GetGPS(long intervalMs) {
        super(intervalMs);
    }

    @Override
    protected Sensor sensor() {
        return Sensor.GPS;
    }
}
