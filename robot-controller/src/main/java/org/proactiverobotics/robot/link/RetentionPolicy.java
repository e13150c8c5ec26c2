package org.proactiverobotics.robot.link;

/**
 * How much reading history the robot keeps, so that a long run does not grow its tables (and
 * the cost of each step) without limit. The robot prunes, for its own robot id, every
 * {@code everySteps} control steps: the readings it writes ({@code gps_stored_values},
 * {@code iudata}, {@code battery_level}, {@code odometry}: the newest {@code keepReadings} rows each;
 * {@code distance_sensor_data}: the newest {@code keepReadings} readings, i.e. that many rows
 * per sensor). {@code sensor_requests}, {@code engine_comments} and the mission rows belong to
 * the engine, which bounds its own history; the robot only reads them (and marks requests
 * answered), so its database user needs no DELETE there.
 *
 * @param keepReadings how many newest readings of each sensor to keep (at least 1)
 * @param everySteps   prune every this many control steps (at least 1)
 */
public record RetentionPolicy(int keepReadings, int everySteps) {

    /**
     * Keeps 1000 readings per sensor (32 s of history at one reading per 32 ms step), pruned every
     * 500 steps: finding the cut-off walks the kept rows, so pruning seldom costs less (every 100
     * steps it was a tenth of an embedded-H2 mission's time, JFR).
     */
    public static final RetentionPolicy DEFAULT = new RetentionPolicy(1000, 500);

    /** Never prunes: every reading is kept (for short runs and post-mortems). */
    public static final RetentionPolicy KEEP_ALL = new RetentionPolicy(Integer.MAX_VALUE, Integer.MAX_VALUE);

    /** Checks the bounds. */
    public RetentionPolicy {
        if (keepReadings < 1 || everySteps < 1) {
            throw new IllegalArgumentException("retention needs keepReadings >= 1 and everySteps >= 1: "
                    + keepReadings + ", " + everySteps);
        }
    }

    /** @return whether this policy ever prunes */
    public boolean prunes() {
        return keepReadings != Integer.MAX_VALUE;
    }
}
