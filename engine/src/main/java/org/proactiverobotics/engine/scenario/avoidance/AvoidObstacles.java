package org.proactiverobotics.engine.scenario.avoidance;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Boundary following with the Pledge algorithm's exit rule (Abelson and diSessa, 1980): when an
 * obstacle comes too close ahead (or too close at a side), the rule takes over, turns to the
 * freer side and follows the obstacle's boundary at a fixed distance, counting how far it has
 * turned. It lets go once the turning is undone (the heading is back to where it met the
 * obstacle, or past it) and the way ahead is clear, so a convex obstacle is passed rather than
 * circled. It needs no goal: the other scenarios keep theirs. Suggests nothing while the way
 * is clear; a stop-and-turn when a collision is imminent.
 */
public final class AvoidObstacles extends Rule {

    /** Engage when anything ahead (±30°) is closer than this, metres from the rim. */
    static final double ENGAGE_FRONT_M = 0.22;
    /** ... or anything straight ahead (±12°) closer than this. */
    static final double ENGAGE_AHEAD_M = 0.30;
    /** ... or anything at a side (45° to 100°) closer than this. */
    static final double ENGAGE_SIDE_M = 0.15;
    /** The distance kept to the followed boundary, metres. */
    static final double WALL_DISTANCE_M = 0.20;
    /** Closer than this ahead: stop and turn on the spot. */
    static final double IMMINENT_M = 0.15;
    /** Release needs this much free space ahead, metres. */
    static final double RELEASE_FRONT_M = 0.45;
    /** ... and the followed side's 45° sensor this clear. */
    static final double RELEASE_SIDE_M = 0.25;
    /** ... for this many iterations in a row. */
    static final int RELEASE_ITERATIONS = 4;
    /** A scan this far behind the heading is stale (its sensor is not being read): driving blind. */
    static final long STALE_SCAN_MS = 500;
    private static final double RELEASE_TURN_RAD = Math.toRadians(20);
    private static final double DEG = Math.PI / 180;

    /** Whether the rule is following a boundary. */
    private boolean following;
    /** +1: the obstacle is kept on the right (the robot turned left); -1: on the left. */
    private int side;
    /** How far the robot has turned since it met the obstacle, radians, counter-clockwise positive. */
    private double turnedRad;
    private double lastYawRad;
    private int clearIterations;

    private transient DistanceScan scan;
    private transient Heading heading;
    private transient String suggestion;

    /** @return whether the rule is following an obstacle's boundary */
    public boolean following() {
        return following;
    }

    @Override
    public String scenario() {
        return ObstacleAvoidanceScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        SensorReadings readings = ctx.service(SensorReadings.class);
        scan = readings.newestScan().orElse(null);
        heading = readings.newestHeading().orElse(null);
    }

    /** Guard: distance readings and the heading are known. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return scan != null && heading != null;
    }

    /**
     * Condition: an obstacle needs avoiding (updates the boundary-following state), or the
     * distance readings have gone stale and the robot must not drive blind (STOP).
     */
    @Override
    protected boolean conditions(RuleContext ctx) {
        if (Math.abs(heading.simTimeMs() - scan.simTimeMs()) > STALE_SCAN_MS) {
            suggestion = Steering.STOP;
            return true;
        }
        DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
        suggestion = decide(scan, heading.yawRad(), profile);
        return suggestion != null;
    }

    @Override
    protected void actions(RuleContext ctx) {
        ctx.suggest(suggestion);
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }

    /** One step of the boundary follower: the command to suggest, or null when the way is clear. */
    String decide(DistanceScan s, double yawRad, DriveProfile profile) {
        double ahead = s.min(-12 * DEG, 12 * DEG);
        double front = s.min(-30 * DEG, 30 * DEG);
        double right = s.min(-100 * DEG, -30 * DEG);
        double left = s.min(30 * DEG, 100 * DEG);
        if (!following) {
            if (front < ENGAGE_FRONT_M || ahead < ENGAGE_AHEAD_M) {
                side = s.sum(12 * DEG, 180 * DEG) >= s.sum(-180 * DEG, -12 * DEG) ? +1 : -1;
            } else if (Math.min(right, left) < ENGAGE_SIDE_M) {
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
        if (turnUndone && front > RELEASE_FRONT_M && side45 > RELEASE_SIDE_M) {
            if (++clearIterations >= RELEASE_ITERATIONS) {
                following = false;
                return null;
            }
        } else {
            clearIterations = 0;
        }

        double max = profile.maxSpeedMps();
        if (front < IMMINENT_M || ahead < IMMINENT_M * 1.2) {
            return Steering.drive(0.0, side * 1.8, profile);
        }
        double wall = side > 0
                ? Math.min(s.min(-100 * DEG, -60 * DEG), 0.75 * side45)
                : Math.min(s.min(60 * DEG, 100 * DEG), 0.75 * side45);
        double frontSide = side > 0 ? s.min(-30 * DEG, -12 * DEG) : s.min(12 * DEG, 30 * DEG);
        double turn = -side * Math.max(-1.6, Math.min(1.6, 4.0 * (wall - WALL_DISTANCE_M)));
        if (frontSide < 0.3) {
            turn = side * 1.5;
        }
        return Steering.drive(0.7 * max, turn, profile);
    }
}
