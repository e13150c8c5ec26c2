package org.proactiverobotics.engine.tables;

import java.util.Optional;

/**
 * The robot's pose estimate as shared rows ({@code pose_estimate}): the localisation scenario
 * writes one per iteration, every scenario that needs the pose reads the newest (in the same
 * iteration, the one just written).
 */
public interface PoseEstimateTable {

    /** @return the newest pose estimate of this robot, if any */
    Optional<PoseEstimate> newestPose();

    /** @param estimate the estimate to store (the newest from now on) */
    void writePose(PoseEstimate estimate);

    /**
     * An estimate kept in memory only: for a communication layer that has no such rows (a
     * benchmark's or a test's own tables, the direct link), so that the scenarios still run.
     *
     * @return an empty table
     */
    static PoseEstimateTable inMemory() {
        return new PoseEstimateTable() {
            private PoseEstimate newest;

            @Override
            public synchronized Optional<PoseEstimate> newestPose() {
                return Optional.ofNullable(newest);
            }

            @Override
            public synchronized void writePose(PoseEstimate estimate) {
                newest = estimate;
            }
        };
    }
}
