package org.proactiverobotics.robot.link;

/**
 * A wheel odometry reading: how far each wheel rolled since the robot's previous odometry
 * reading, positive forwards (turning on the spot gives opposite signs).
 *
 * @param leftM  the left wheel's travel, metres
 * @param rightM the right wheel's travel, metres
 */
public record OdometryReading(double leftM, double rightM) {
}
