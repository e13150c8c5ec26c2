package org.proactiverobotics.engine.tables;

/**
 * Where the robot stands when its mission starts ({@code initial_pose}, a mission row): what an
 * operator gives a robot that has no GPS (the "initial pose" a localiser starts from), seeded
 * from the world file by the robot side like the checkpoints.
 *
 * @param xM     x, metres
 * @param yM     y, metres
 * @param yawRad heading, radians, counter-clockwise from +x
 */
public record InitialPose(double xM, double yM, double yawRad) {
}
