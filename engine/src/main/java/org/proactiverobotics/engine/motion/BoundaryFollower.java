package org.proactiverobotics.engine.motion;

import org.proactiverobotics.engine.tables.DistanceScan;

/**
 * Boundary following with the Pledge algorithm's exit rule (Abelson and diSessa, 1980), as a
 * reflex any scenario may hold: when an obstacle comes too close ahead (or too close at a side)
 * it takes over, turns to the freer side and follows the obstacle's boundary, counting how far it
 * has turned. It lets go once the turning is undone (the heading is back to where it met the
 * obstacle, or past it) and the way ahead is clear, so a convex obstacle is passed rather than
 * circled; or once it has turned a full circle and the way ahead is clear (it is going round an
 * enclosure or circling, not passing an obstacle, and another lap would only repeat the first).
 * The distances come from a {@link Clearance}. Plain fields, so it is saved with the rule that
 * holds it.
 */
public final class BoundaryFollower {

    /** Release needs the way clear for this many iterations in a row. */
    static final int RELEASE_ITERATIONS = 4;
    private static final double RELEASE_TURN_RAD = Math.toRadians(20);
    private static final double FULL_CIRCLE_RAD = 2 * Math.PI;
    private static final double DEG = Math.PI / 180;

    /** Whether it is following a boundary. */
    private boolean following;
    /** +1: the obstacle is kept on the right (the robot turned left); -1: on the left. */
    private int side;
    /** How far the robot has turned since it met the obstacle, radians, counter-clockwise positive. */
    private double turnedRad;
    private double lastYawRad;
    private int clearIterations;

    /** @return whether it is following an obstacle's boundary */
    public boolean following() {
        return following;
    }

    /** Lets go of the boundary at once: the holder has found its own way clear. */
    public void release() {
        following = false;
        clearIterations = 0;
    }

    /**
     * One step.
     *
     * @param s         the newest distance scan
     * @param yawRad    the robot's heading, radians
     * @param profile   the robot's drive
     * @param clearance the distances to keep
     * @return the command to suggest, or null when the way is clear and nothing needs avoiding
     */
    public String decide(DistanceScan s, double yawRad, DriveProfile profile, Clearance clearance) {
        double ahead = s.min(-12 * DEG, 12 * DEG);
        double front = s.min(-30 * DEG, 30 * DEG);
        double right = s.min(-100 * DEG, -30 * DEG);
        double left = s.min(30 * DEG, 100 * DEG);
        if (!following) {
            if (front < clearance.engageFrontM() || ahead < clearance.engageAheadM()) {
                side = s.sum(12 * DEG, 180 * DEG) >= s.sum(-180 * DEG, -12 * DEG) ? +1 : -1;
            } else if (Math.min(right, left) < clearance.engageSideM()) {
                side = right <= left ? +1 : -1;
            } else {
                return null;
            }
            following = true;
            turnedRad = 0;
            lastYawRad = yawRad;
            clearIterations = 0;
        }
        turnedRad += Steering.wrap(yawRad - lastYawRad);
        lastYawRad = yawRad;

        double side45 = side > 0 ? s.min(-60 * DEG, -30 * DEG) : s.min(30 * DEG, 60 * DEG);
        boolean turnUndone = side * turnedRad < RELEASE_TURN_RAD;
        boolean passed = turnUndone && front > clearance.releaseFrontM() && side45 > clearance.releaseSideM();
        boolean circled = Math.abs(turnedRad) >= FULL_CIRCLE_RAD && front > clearance.releaseFrontM();
        if (passed || circled) {
            if (++clearIterations >= RELEASE_ITERATIONS) {
                following = false;
                return null;
            }
        } else {
            clearIterations = 0;
        }

        double max = profile.maxSpeedMps();
        if (front < clearance.imminentM() || ahead < clearance.imminentM() * 1.2) {
            return Steering.drive(0.0, side * 1.8, profile);
        }
        double wall = side > 0
                ? Math.min(s.min(-100 * DEG, -60 * DEG), 0.75 * side45)
                : Math.min(s.min(60 * DEG, 100 * DEG), 0.75 * side45);
        double frontSide = side > 0 ? s.min(-30 * DEG, -12 * DEG) : s.min(12 * DEG, 30 * DEG);
        double turn = -side * Math.max(-1.6, Math.min(1.6, 4.0 * (wall - clearance.wallDistanceM())));
        if (frontSide < clearance.engageAheadM()) {
            turn = side * 1.5;
        }
        return Steering.drive(0.7 * max, turn, profile);
    }
}
