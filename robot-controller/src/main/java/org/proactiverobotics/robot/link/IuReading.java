package org.proactiverobotics.robot.link;

/**
 * An inertial unit reading; yaw 0 = +x axis, counter-clockwise positive.
 *
 * @param rollRad  roll in radians
 * @param pitchRad pitch in radians
 * @param yawRad   yaw in radians
 */
public record IuReading(double rollRad, double pitchRad, double yawRad) {
}
