package org.proactiverobotics.robot.link;

/**
 * A GPS reading.
 *
 * @param xM x in metres
 * @param yM y in metres
 */
public record GpsReading(double xM, double yM) {
}
