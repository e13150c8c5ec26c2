package org.proactiverobotics.engine.scenario.destination;

import java.util.Locale;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.navigation.LookAgainAsks;
import org.proactiverobotics.engine.navigation.RouteFollower;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;

/**
 * Steers toward one checkpoint from the pose estimate (the Localisation scenario's), cloning itself until the
 * checkpoint is reached; then marks it reached and generates GetCheckpoint. It follows a route
 * planned on the occupancy map known so far (unknown cells free) and re-planned as scans reveal
 * walls ({@link RouteFollower}): straight at the checkpoint while the map shows the way clear, else
 * at the farthest waypoint in sight. When the planner has found no route at all for
 * {@value #NO_ROUTE_MS} ms of simulated time (the robot stopped, scanning: a wall a noisy reading
 * drew across a doorway is cleared by the rays that pass through it; in a world shared with other
 * robots, {@link SharedWorld#noRouteMs()}), it marks the checkpoint
 * unreachable and generates GetCheckpoint (which then stops the robot). When the robot makes no
 * progress along the route for {@value RouteFollower#STALL_MS} ms (a gap too tight for the collision
 * monitor), the follower closes that place on its map, backs off and plans round it
 * ({@link RouteFollower}); with no other way left, no plan finds a route, as above.
 */
public final class MoveToCheckpoint extends Rule {

    /** How long no plan finds a route before the checkpoint is declared unreachable, simulated ms. */
    static final long NO_ROUTE_MS = 3_000;

    private int seq;
    private double xM;
    private double yM;
    private double radiusM;
    /** The route and its re-planning (saved with the rule). */
    private RouteFollower route = new RouteFollower();
    /** The side the robot last turned to, +1 left, -1 right, 0 none: kept for a target straight behind. */
    private int behindSide;
    /** The simulated time since which no plan has found a route, ms (-1: the last plan found one). */
    private long noRouteSinceMs = -1;
    /** Its asks to look again while no route is found (saved with the rule). */
    private LookAgainAsks lookAgainAsks = new LookAgainAsks();

    private transient PoseEstimate position;
    private transient boolean reached;
    private transient boolean unreachable;

    private MoveToCheckpoint() {
    }
    /**
     * @param seq     the checkpoint's place in the order
     * @param xM      its x, metres
     * @param yM      its y, metres
     * @param radiusM how close counts as reached, metres
     */
    public MoveToCheckpoint(int seq, double xM, double yM, double radiusM) {
        this.seq = seq;
        this.xM = xM;
        this.yM = yM;
        this.radiusM = radiusM;
    }

    /** @return the checkpoint this rule steers to */
    public int seq() {
        return seq;
    }

    @Override
    public String scenario() {
        return ReachDestinationScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        position = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
    }

    /** Guard: the robot's pose is known (the localisation's estimate). */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return position != null && position.knowsHeading();
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return true;
    }

    @Override
    protected void actions(RuleContext ctx) {
        BeliefObserver belief = ctx.findService(BeliefObserver.class).orElse(null);
        reached = position.distanceTo(xM, yM) < radiusM * Checkpoint.REACHED_FRACTION;
        if (reached) {
            ctx.service(MissionTables.class).markReached(seq, position.simTimeMs());
            if (belief != null) {
                belief.route(ctx.iteration(), scenario(), new double[0], new double[0]); // this route ends here
            }
            return;
        }
        DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
        OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), position.simTimeMs());
        RouteFollower.Status status = route.step(map, position.xM(), position.yM(), position.yawRad(), xM, yM,
                Checkpoint.routeReachM(radiusM), profile.axleWidthM() / 2, position.simTimeMs(), drivingForThis(ctx),
                ctx.findService(SharedWorld.class).isPresent());
        if (belief != null && route.closedNow()) {
            belief.wayClosed(ctx.iteration(), scenario(), route.closed().newestReason());
        }
        if (belief != null && route.planned()) {
            belief.route(ctx.iteration(), scenario(), route.waypointsX(), route.waypointsY());
        }
        if (status == RouteFollower.Status.BACK_OFF) {
            ctx.suggest(RouteFollower.backOffCommand(profile));
            return;
        }
        if (status == RouteFollower.Status.NO_ROUTE) {
            if (noRouteSinceMs < 0) {
                noRouteSinceMs = position.simTimeMs();
            }
            // in a shared world a robot standing in the only door is no wall: it is waited for longer
            long patienceMs = ctx.findService(SharedWorld.class).map(SharedWorld::noRouteMs).orElse(NO_ROUTE_MS);
            if (ctx.findService(SharedWorld.class).isPresent()) {
                lookAgain(ctx);
            }
            if (position.simTimeMs() - noRouteSinceMs >= patienceMs) {
                unreachable = true;
                ctx.service(MissionTables.class).markUnreachable(seq, position.simTimeMs());
                if (belief != null) {
                    belief.checkpointUnreachable(ctx.iteration(), seq, unreachableReason(position.simTimeMs() - noRouteSinceMs));
                }
            }
            ctx.suggest(Steering.STOP);
            return;
        }
        noRouteSinceMs = -1;
        behindSide = Steering.turnSide(position.xM(), position.yM(), position.yawRad(), route.targetX(), route.targetY(), behindSide);
        ctx.suggest(Steering.goTo(position.xM(), position.yM(), position.yawRad(), route.targetX(), route.targetY(), profile, behindSide));
    }

    /**
     * In a shared world, after {@value LookAgainAsks#AFTER_MS} ms without a route (and as long after the
     * last ask), asks the mapping to let go of the cells other robots moved into, at most
     * {@value LookAgainAsks#LIMIT} times: Nav2's clearing of the costmap, for the moving cells alone. A blob
     * a robot left where the map does not let it fade may be all that walls the way, and the robot, never
     * going back to look, waited until the checkpoint was declared unreachable (6 robots in 120 worlds of four).
     */
    private void lookAgain(RuleContext ctx) {
        lookAgainAsks.askWhenDue(ctx.memory().values(), noRouteSinceMs, position.simTimeMs());
    }

    /** What the engine knows of why: no plan on its map found a way to the checkpoint for so long. */
    private String unreachableReason(long forMs) {
        String why = String.format(Locale.ROOT, "no route to checkpoint %d (index %d) at (%.2f, %.2f) on the map from (%.2f, %.2f):"
                        + " every plan for %.1f s found none (%d in a row), the way walled in as the map has it",
                seq + 1, seq, xM, yM, position.xM(), position.yM(), forMs / 1000.0, route.plansWithoutRoute());
        if (route.closed().isEmpty()) {
            return why;
        }
        return why + (route.boxedIn() ? ", the robot boxed in by" : " and") + " the narrow places closed where it made no progress: "
                + route.closed().describe();
    }

    /** Whether the robot drove for this rule's route last iteration: its command won, or the collision monitor vetoed it. */
    private boolean drivingForThis(RuleContext ctx) {
        return RouteFollower.droveFor(ctx.memory().values().get(SharedMemory.LAST_DECISION), scenario());
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(reached || unreachable ? new GetCheckpoint() : this);
    }
}
