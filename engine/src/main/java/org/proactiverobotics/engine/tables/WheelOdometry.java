package org.proactiverobotics.engine.tables;

/**
 * A wheel odometry reading: how far each wheel rolled since the robot's previous odometry
 * reading, positive forwards; turning on the spot gives opposite signs.
 *
 * @param simTimeMs simulated time of the reading, milliseconds
 * @param leftM     the left wheel's travel, metres
 * @param rightM    the right wheel's travel, metres
 */
public record WheelOdometry(long simTimeMs, double leftM, double rightM) {
}
