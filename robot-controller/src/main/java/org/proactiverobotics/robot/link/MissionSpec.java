package org.proactiverobotics.robot.link;

import java.util.List;

/**
 * The mission rows a robot seeds once from its world file: the checkpoints (in visiting order),
 * the recharge station, the level a recharge stops at, and where the robot starts.
 *
 * @param checkpoints       the checkpoints, in the order to reach them
 * @param station           the recharge station
 * @param rechargeToPct     the battery level (percent) a recharge stops at ({@code battery_recharged})
 * @param start             where the robot starts ({@code initial_pose}), or null: none given
 */
public record MissionSpec(List<Checkpoint> checkpoints, Station station, double rechargeToPct, Start start) {

    /** Defensive copy. */
    public MissionSpec {
        checkpoints = List.copyOf(checkpoints);
    }

    /**
     * A mission without an initial pose.
     *
     * @param checkpoints   the checkpoints, in the order to reach them
     * @param station       the recharge station
     * @param rechargeToPct the battery level (percent) a recharge stops at
     */
    public MissionSpec(List<Checkpoint> checkpoints, Station station, double rechargeToPct) {
        this(checkpoints, station, rechargeToPct, null);
    }

    /**
     * Where the robot starts: the initial pose a localiser is given.
     *
     * @param xM     x in metres
     * @param yM     y in metres
     * @param yawRad heading in radians, counter-clockwise from +x
     */
    public record Start(double xM, double yM, double yawRad) {
    }

    /**
     * A checkpoint.
     *
     * @param xM      x in metres
     * @param yM      y in metres
     * @param radiusM how close counts as reached, metres
     */
    public record Checkpoint(double xM, double yM, double radiusM) {
    }

    /**
     * The recharge station.
     *
     * @param xM      x in metres
     * @param yM      y in metres
     * @param radiusM how close counts as at the station, metres
     */
    public record Station(double xM, double yM, double radiusM) {
    }
}
