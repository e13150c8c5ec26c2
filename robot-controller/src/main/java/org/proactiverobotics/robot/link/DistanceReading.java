package org.proactiverobotics.robot.link;

/**
 * One distance sensor's reading (one row of {@code distance_sensor_data}).
 *
 * @param sensorIndex the sensor's index on the robot
 * @param angleRad    the sensor's direction relative to the robot's heading, radians
 * @param distanceM   the measured distance in metres; equals {@code rangeM} when nothing is hit
 * @param rangeM      the sensor's range in metres
 */
public record DistanceReading(int sensorIndex, double angleRad, double distanceM, double rangeM) {
}
