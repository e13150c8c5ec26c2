package org.proactiverobotics.robot.link;

import java.util.List;

/**
 * The mission rows a robot seeds once from its world file: the checkpoints (in visiting order),
 * the recharge station, and the level a recharge stops at.
 *
 * @param checkpoints       the checkpoints, in the order to reach them
 * @param station           the recharge station
 * @param rechargeToPct     the battery level (percent) a recharge stops at ({@code battery_recharged})
 */
public record MissionSpec(List<Checkpoint> checkpoints, Station station, double rechargeToPct) {

    /** Defensive copy. */
    public MissionSpec {
        checkpoints = List.copyOf(checkpoints);
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
