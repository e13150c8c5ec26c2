package org.proactiverobotics.sim2d;

/**
 * What really happened, for reports: the simulator's truth, never what a controller believes.
 * Updated by the {@link Simulation} after every step; read-only for everyone else.
 */
public final class GroundTruth {

    private final int checkpointsTotal;
    double x;
    double y;
    double headingRad;
    double distanceM;
    int collisions;
    int robotCollisions;
    double minClearanceM = Double.POSITIVE_INFINITY;
    int checkpointsReached;
    double batteryPct;
    double minBatteryPct;
    int recharges;

    GroundTruth(int checkpointsTotal) {
        this.checkpointsTotal = checkpointsTotal;
    }

    /** @return the robot centre's x, metres */
    public double x() {
        return x;
    }

    /** @return the robot centre's y, metres */
    public double y() {
        return y;
    }

    /** @return the heading, radians in (-π, π], 0 along +x, counter-clockwise positive */
    public double headingRad() {
        return headingRad;
    }

    /** @return the distance the robot's centre has travelled, metres */
    public double distanceM() {
        return distanceM;
    }

    /**
     * @return how many times the robot came into contact with a wall, an obstacle or another robot it was not
     *         touching; includes {@link #robotCollisions()} (a collision is a collision)
     */
    public int collisions() {
        return collisions;
    }

    /**
     * @return how many of {@link #collisions()} were with another robot; each such contact counts once for
     *         each of the two robots
     */
    public int robotCollisions() {
        return robotCollisions;
    }

    /**
     * @return the smallest gap seen between the robot's rim and any wall or obstacle (not other robots), metres (0 when they
     * touched), sampled at the start and after every step
     */
    public double minClearanceM() {
        return minClearanceM;
    }

    /** @return how many checkpoints were reached, in the listed order */
    public int checkpointsReached() {
        return checkpointsReached;
    }

    /** @return how many checkpoints the world has */
    public int checkpointsTotal() {
        return checkpointsTotal;
    }

    /** @return whether every checkpoint was reached */
    public boolean allCheckpointsReached() {
        return checkpointsReached == checkpointsTotal;
    }

    /** @return the battery level now, percent */
    public double batteryPct() {
        return batteryPct;
    }

    /** @return the lowest battery level seen, percent */
    public double minBatteryPct() {
        return minBatteryPct;
    }

    /** @return how many charging sessions were started */
    public int recharges() {
        return recharges;
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT,
                "GroundTruth[x=%.3f, y=%.3f, heading=%.3f rad, distance=%.3f m, collisions=%d, minClearance=%.3f m, "
                        + "checkpoints=%d/%d, battery=%.2f%%, minBattery=%.2f%%, recharges=%d]",
                x, y, headingRad, distanceM, collisions, minClearanceM, checkpointsReached, checkpointsTotal,
                batteryPct, minBatteryPct, recharges);
    }
}
