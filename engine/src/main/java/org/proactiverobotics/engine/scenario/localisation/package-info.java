/**
 * Localisation: EstimatePose keeps the robot's pose estimate with an extended Kalman filter
 * ({@link org.proactiverobotics.engine.scenario.localisation.PoseFilter}) that predicts from wheel
 * odometry and corrects with the inertial unit's heading, the GPS when there is a fix, and, when
 * there is none, the distance scan matched against the engine's own occupancy map
 * ({@link org.proactiverobotics.engine.scenario.localisation.ScanMatcher}). The estimate goes to
 * {@code pose_estimate} in the iteration's transaction; the filter's state is saved with the rule.
 */
package org.proactiverobotics.engine.scenario.localisation;
