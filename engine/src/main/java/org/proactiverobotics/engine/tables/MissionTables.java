package org.proactiverobotics.engine.tables;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;

/** The mission rows: checkpoints, the recharge station and the level a recharge stops at. */
public interface MissionTables {

    /** @return the checkpoints in visiting order */
    List<Checkpoint> checkpoints();

    /**
     * Marks a checkpoint reached.
     *
     * @param seq       the checkpoint
     * @param simTimeMs when, simulated milliseconds
     */
    void markReached(int seq, long simTimeMs);

    /**
     * Marks a checkpoint unreachable: no route leads to it, the mission ends there.
     *
     * @param seq       the checkpoint
     * @param simTimeMs when, simulated milliseconds
     */
    default void markUnreachable(int seq, long simTimeMs) {
        throw new UnsupportedOperationException("these mission tables cannot mark checkpoint " + seq + " unreachable");
    }

    /** @return the recharge station, if the mission has one */
    Optional<Station> rechargeStation();

    /** @return the level a recharge stops at ({@code battery_recharged}), percent */
    OptionalDouble rechargeLevelPct();

    /** @return where the robot stood when the mission started ({@code initial_pose}), if the mission says */
    default Optional<InitialPose> initialPose() {
        return Optional.empty();
    }
}
