package org.proactiverobotics.engine.motion;

/**
 * The control period, measured as the time between two successive readings of one sensor (the
 * engine is not told the world's time step). Plain fields, so it is saved with the rule that
 * holds it.
 */
public final class ControlPeriod {

    /** Longer gaps are a pause (a restart, an outage), not the period, milliseconds. */
    private static final long LONGEST_MS = 1000;

    private long lastMs = -1;
    private long periodMs = Clearance.DEFAULT_PERIOD_MS;

    /**
     * @param simTimeMs the newest reading's simulated time, milliseconds
     * @return the period measured so far (the default until two readings have been seen), milliseconds
     */
    public long observe(long simTimeMs) {
        long gap = simTimeMs - lastMs;
        if (lastMs >= 0 && gap > 0 && gap <= LONGEST_MS) {
            periodMs = gap;
        }
        lastMs = simTimeMs;
        return periodMs;
    }
}
