package org.proactiverobotics.engine.scenario.dataacquisition;

import org.proactiverobotics.engine.tables.Sensor;

/** Keeps a recent reading of the battery level in the database (default interval 320 ms: every 320 simulated ms). */
public final class GetBattery extends SensorWatch {

    /** The default interval, simulated milliseconds. */
    public static final long DEFAULT_INTERVAL_MS = 320;

    /** A watch with the default interval. */
    public GetBattery() {
        this(DEFAULT_INTERVAL_MS);
    }

    /** @param intervalMs how old the newest reading may be, simulated milliseconds */
    public GetBattery(long intervalMs) {
        super(intervalMs);
    }

    @Override
    protected Sensor sensor() {
        return Sensor.BATTERY;
    }
}
