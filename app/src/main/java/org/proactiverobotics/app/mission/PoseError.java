package org.proactiverobotics.app.mission;

/**
 * How far the pose the engine believed was from the simulator's ground truth over a mission
 * (report.json's {@code poseError}, docs/report.md): one sample per engine iteration from the
 * first in which the engine had a pose. Today the engine's pose is its newest GPS reading and
 * inertial-unit heading; a localiser's estimate is measured the same way.
 *
 * @param meanM          the mean distance between believed and true position, metres
 * @param maxM           the largest such distance, metres
 * @param meanHeadingRad the mean absolute heading difference, wrapped to [0, π], radians
 * @param maxHeadingRad  the largest such difference, radians
 * @param samples        the iterations measured
 */
public record PoseError(double meanM, double maxM, double meanHeadingRad, double maxHeadingRad, long samples) {
}
