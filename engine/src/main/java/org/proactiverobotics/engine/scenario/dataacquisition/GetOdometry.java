package org.proactiverobotics.engine.scenario.dataacquisition;

import org.proactiverobotics.engine.tables.Sensor;

/**
 * Keeps a recent wheel odometry reading in the database (default interval 0 ms: every
 * iteration, so that the readings, each the travel since the one before, follow the whole path).
 */
public final class GetOdometry extends SensorWatch {

    /** The default interval, simulated milliseconds. */
    public static final long DEFAULT_INTERVAL_MS = 0;

    /** A watch with the default interval. */
    public GetOdometry() {
        this(DEFAULT_INTERVAL_MS);
    }

    /** @param intervalMs how old the newest reading may be, simulated milliseconds */
    public GetOdometry(long intervalMs) {
        super(intervalMs);
    }

    @Override
    protected Sensor sensor() {
        return Sensor.ODOMETRY;
    }
}
