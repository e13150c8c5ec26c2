package org.proactiverobotics.engine.scenario.avoidance;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.BoundaryFollower;
import org.proactiverobotics.engine.motion.Clearance;
import org.proactiverobotics.engine.motion.ControlPeriod;
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
 * circled (or once it has gone a full circle: see {@link BoundaryFollower}). The distances are
 * derived from the robot's speed, body, control period and sensor range ({@link Clearance}). It needs no goal: the other scenarios keep theirs. Suggests nothing while the way
 * is clear; a stop-and-turn when a collision is imminent.
 */
public final class AvoidObstacles extends Rule {

    /** A scan this far behind the heading is stale (its sensor is not being read): driving blind. */
    static final long STALE_SCAN_MS = 500;

    /** The Pledge boundary follower, the shared reflex (its state is this rule's state). */
    private BoundaryFollower follower = new BoundaryFollower();
    /** Measures the control period from the scans' clock, for the clearance distances. */
    private ControlPeriod period = new ControlPeriod();

    private transient DistanceScan scan;
    private transient Heading heading;
    private transient String suggestion;

    /** @return whether the rule is following an obstacle's boundary */
    public boolean following() {
        return follower.following();
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
        Clearance clearance = Clearance.of(profile, period.observe(s.simTimeMs()), s.rangeM());
        return follower.decide(s, yawRad, profile, clearance);
    }
}
