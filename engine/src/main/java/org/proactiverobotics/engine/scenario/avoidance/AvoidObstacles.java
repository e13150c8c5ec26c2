package org.proactiverobotics.engine.scenario.avoidance;

import java.util.Locale;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.Clearance;
import org.proactiverobotics.engine.motion.CollisionReflex;
import org.proactiverobotics.engine.motion.ControlPeriod;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Keeps the robot from hitting things, as a collision monitor: every iteration it vets the command
 * that would win without it (the highest-priority suggestion entered this iteration, as the
 * CommandArray and PriorityArray hold it) with the shared collision reflex ({@link CollisionReflex})
 * and suggests a turn on the spot only when that command would bring the body into something
 * within its braking reach. So it speaks only to prevent a collision, never to keep following a
 * wall, and the scenarios that find the way (which plan on the map) drive everywhere else,
 * doorways and corridors included; a strategy that ranks it first lets nothing overrule that.
 * The reach comes from the robot's speed, control period and sensor range ({@link Clearance}).
 * STOP when the distance readings have gone stale. In a world shared with other robots, or on a
 * robot with rays that look behind (beyond ±90°), it vets reverse commands too: backing toward
 * something seen, or into cells never seen, within the braking reach is replaced by STOP.
 */
public final class AvoidObstacles extends Rule {

    /** A scan this far behind the heading is stale (its sensor is not being read): driving blind. */
    static final long STALE_SCAN_MS = 500;

    /** Measures the control period from the scans' clock, for the clearance distances. */
    private ControlPeriod period = new ControlPeriod();
    /** The reflex (its state is this rule's state). */
    private CollisionReflex reflex = new CollisionReflex();

    private transient DistanceScan scan;
    private transient Heading heading;
    private transient PoseEstimate position;
    private transient String suggestion;

    /** @return whether the reflex vetoed the last command it vetted */
    public boolean engaged() {
        return reflex.engaged();
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
        position = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
    }

    /** Guard: distance readings and the heading are known (without a position, hits are not remembered). */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return scan != null && heading != null;
    }

    /**
     * Condition: an obstacle is too close to go on as the robot is going, or the distance readings
     * have gone stale and the robot must not drive blind (STOP).
     */
    @Override
    protected boolean conditions(RuleContext ctx) {
        BeliefObserver belief = ctx.findService(BeliefObserver.class).orElse(null);
        String intended = intended(ctx);
        if (Math.abs(heading.simTimeMs() - scan.simTimeMs()) > STALE_SCAN_MS) {
            suggestion = Steering.STOP;
            if (belief != null) {
                belief.vetoed(ctx.iteration(), String.format(Locale.ROOT,
                        "vetoed %s: the distance readings are %.3f s older than the heading, not driving blind",
                        intended == null ? "no command" : intended, (heading.simTimeMs() - scan.simTimeMs()) / 1000.0));
            }
            return true;
        }
        DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
        if (ctx.findService(SharedWorld.class).isPresent() || looksBehind(scan)) {
            reflex.vettingReverse();
        }
        OccupancyMap map = position == null ? null
                : ctx.findService(KnownMap.class).map(m -> m.current(ctx.iteration(), position.simTimeMs())).orElse(null);
        suggestion = reflex.vet(intended, scan, map, position == null ? 0.0 : position.xM(),
                position == null ? 0.0 : position.yM(), position == null || !position.knowsHeading() ? heading.yawRad() : position.yawRad(), profile,
                Clearance.of(profile, period.observe(scan.simTimeMs()), scan.rangeM()));
        if (position == null) {
            reflex.forget(); // without a position the hits cannot be placed: only this scan counted
        }
        if (suggestion != null && belief != null) {
            String reason = reflex.reason(intended);
            if (reason != null) {
                belief.vetoed(ctx.iteration(), reason);
            }
        }
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

    /** @return whether a ray of the scan looks behind the robot (beyond ±90° from the heading) */
    static boolean looksBehind(DistanceScan s) {
        for (double a : s.anglesRad()) {
            if (Math.abs(a) > Math.PI / 2 + 1e-6) {
                return true;
            }
        }
        return false;
    }

    /**
     * The command that would win without this scenario: the highest-priority suggestion entered this
     * iteration by another scenario; when none is there yet (a scenario restarted by the fail-safe
     * runs after this one, and one-iteration suggestions go after each decision), the last decision's
     * command, which it is about to repeat, unless that was this scenario's own.
     */
    private static String intended(RuleContext ctx) {
        SharedMemory memory = ctx.memory();
        for (int slot : memory.priorityArray().slotsByPriority()) {
            Suggestion s = memory.commandArray().get(slot);
            if (s != null && s.iteration() == ctx.iteration() && !ObstacleAvoidanceScenario.NAME.equals(s.scenario())) {
                return s.command();
            }
        }
        String last = memory.values().get(SharedMemory.LAST_DECISION);
        if (last == null || last.startsWith(ObstacleAvoidanceScenario.NAME + " ")) {
            return null;
        }
        return last.substring(last.indexOf(' ') + 1);
    }
}
