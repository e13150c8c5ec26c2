package org.proactiverobotics.engine.tables;

/**
 * An inertial-unit reading, reduced to what a ground robot needs.
 *
 * @param simTimeMs simulated time of the reading, milliseconds
 * @param yawRad    heading, radians; 0 = +x axis, counter-clockwise positive
 */
public record Heading(long simTimeMs, double yawRad) {
}
