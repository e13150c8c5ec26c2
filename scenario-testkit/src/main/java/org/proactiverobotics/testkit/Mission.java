package org.proactiverobotics.testkit;

/**
 * The mission rows the robot seeds before it starts (from its world file, in a real run): the
 * checkpoints to reach in order, the recharge station, and where the robot starts (the initial
 * pose a robot without GPS localises from). Each row is written at once.
 *
 * <p>Units: metres, degrees, percent (0 to 100).
 */
public final class Mission {

    /** A checkpoint's radius unless given, metres. */
    public static final double CHECKPOINT_RADIUS_M = 0.25;
    /** The station's radius, metres. */
    public static final double STATION_RADIUS_M = 0.35;

    private final int robotId;
    private final KitDatabase db;
    private int nextSeq;

    Mission(int robotId, KitDatabase db) {
        this.robotId = robotId;
        this.db = db;
    }

    /**
     * Adds the next checkpoint (sequence numbers 0, 1, 2, ... in the order added), radius
     * {@value #CHECKPOINT_RADIUS_M} m.
     *
     * @param xM where, metres
     * @param yM where, metres
     * @return this mission
     */
    public Mission checkpoint(double xM, double yM) {
        return checkpoint(xM, yM, CHECKPOINT_RADIUS_M);
    }

    /**
     * Adds the next checkpoint.
     *
     * @param xM      where, metres
     * @param yM      where, metres
     * @param radiusM how close counts as reached, metres
     * @return this mission
     */
    public Mission checkpoint(double xM, double yM, double radiusM) {
        db.update("INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m) VALUES (?, ?, ?, ?, ?)",
                robotId, nextSeq++, xM, yM, radiusM);
        return this;
    }

    /**
     * Sets the recharge station (one per robot), radius {@value #STATION_RADIUS_M} m.
     *
     * @param xM            where, metres
     * @param yM            where, metres
     * @param rechargeToPct the battery level a recharge stops at, percent
     * @return this mission
     */
    public Mission station(double xM, double yM, double rechargeToPct) {
        db.update("DELETE FROM recharge_station WHERE robot_id = ?", robotId);
        db.update("DELETE FROM battery_recharged WHERE robot_id = ?", robotId);
        db.update("INSERT INTO recharge_station (robot_id, x_m, y_m, radius_m) VALUES (?, ?, ?, ?)",
                robotId, xM, yM, STATION_RADIUS_M);
        db.update("INSERT INTO battery_recharged (robot_id, level_pct) VALUES (?, ?)", robotId, rechargeToPct);
        return this;
    }

    /**
     * Sets where the robot starts ({@code initial_pose}): the pose the Localisation scenario starts
     * its estimate from, as an operator gives a robot without GPS its initial pose.
     *
     * @param xM     where, metres
     * @param yM     where, metres
     * @param yawDeg the heading, degrees: 0 faces +x, counter-clockwise positive
     * @return this mission
     */
    public Mission initialPose(double xM, double yM, double yawDeg) {
        db.update("DELETE FROM initial_pose WHERE robot_id = ?", robotId);
        db.update("INSERT INTO initial_pose (robot_id, x_m, y_m, yaw_rad) VALUES (?, ?, ?, ?)", robotId, xM, yM,
                Math.toRadians(yawDeg));
        return this;
    }
}
