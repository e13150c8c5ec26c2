package org.proactiverobotics.engine.scenario.destination;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.OccupancyMapTable;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Steers toward one checkpoint from the GPS and inertial-unit readings, cloning itself until the
 * checkpoint is reached; then marks it reached and generates GetCheckpoint. It follows a route
 * planned on the occupancy map known so far ({@link OccupancyMapTable}, unknown cells free),
 * re-planned every {@value #REPLAN_EVERY} iterations as the map grows: it steers straight at the
 * checkpoint while the way there is clear on the map, else at the farthest point of the route it
 * can see. When {@value #NO_ROUTE_PLANS} plans in a row find no route at all, it marks the
 * checkpoint unreachable and generates GetCheckpoint (which then stops the robot).
 */
public final class MoveToCheckpoint extends Rule {

    /** Counts as reached a little inside the checkpoint's radius, so the simulator agrees. */
    static final double REACHED_FRACTION = 0.8;
    /**
     * Re-plan the route every this many iterations: every one, because the route is not saved with
     * the engine state (its grid is large), so a resumed engine must plan as the uninterrupted one did.
     */
    static final int REPLAN_EVERY = 1;
    /** Plans in a row without a route before the checkpoint is declared unreachable. */
    static final int NO_ROUTE_PLANS = 3;
    /** The farthest route point the robot steers at, metres along the route. */
    static final double LOOKAHEAD_M = 2.0;

    private int seq;
    private double xM;
    private double yM;
    private double radiusM;

    /** Iterations since the last plan (a fresh rule plans at once). */
    private int sincePlan = REPLAN_EVERY;
    /** Plans in a row that found no route. */
    private int plansWithoutRoute;

    private transient GpsFix position;
    private transient Heading heading;
    private transient boolean reached;
    private transient boolean unreachable;
    private transient RoutePlanner.Route route;

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
        SensorReadings readings = ctx.service(SensorReadings.class);
        position = readings.newestGps().orElse(null);
        heading = readings.newestHeading().orElse(null);
    }

    /** Guard: the robot's position and heading are known. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return position != null && heading != null;
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return true;
    }

    @Override
    protected void actions(RuleContext ctx) {
        reached = position.distanceTo(xM, yM) < radiusM * REACHED_FRACTION;
        if (reached) {
            ctx.service(MissionTables.class).markReached(seq, position.simTimeMs());
            return;
        }
        DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
        double robotRadiusM = profile.axleWidthM() / 2;
        if (route == null || ++sincePlan >= REPLAN_EVERY) {
            sincePlan = 0;
            OccupancyMap map = OccupancyMap.of(ctx.service(OccupancyMapTable.class).readMap());
            RoutePlanner.Route planned = RoutePlanner.plan(map, position.xM(), position.yM(), xM, yM,
                    radiusM * REACHED_FRACTION * 0.9, robotRadiusM);
            if (planned == null) {
                if (++plansWithoutRoute >= NO_ROUTE_PLANS) {
                    unreachable = true;
                    ctx.service(MissionTables.class).markUnreachable(seq, position.simTimeMs());
                    ctx.suggest(Steering.STOP);
                    return;
                }
            } else {
                plansWithoutRoute = 0;
                route = planned;
            }
        }
        double[] target = target(robotRadiusM);
        String command = Steering.goTo(position.xM(), position.yM(), heading.yawRad(), target[0], target[1], profile);
        ctx.suggest(command);
    }

    /** The checkpoint when the map shows a clear way, else the farthest visible point of the route. */
    private double[] target(double robotRadiusM) {
        double px = position.xM();
        double py = position.yM();
        if (route == null || route.grid().visible(px, py, xM, yM, RoutePlanner.START_CLEAR_M)) {
            return new double[] {xM, yM};
        }
        double[] xs = route.xs();
        double[] ys = route.ys();
        int nearest = 0;
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < xs.length; k++) {
            double d = Math.hypot(xs[k] - px, ys[k] - py);
            if (d < best) {
                best = d;
                nearest = k;
            }
        }
        int chosen = Math.min(nearest + 1, xs.length - 1);
        double along = 0;
        for (int k = nearest + 1; k < xs.length; k++) {
            along += Math.hypot(xs[k] - xs[k - 1], ys[k] - ys[k - 1]);
            if (along > LOOKAHEAD_M) {
                break;
            }
            if (route.grid().visible(px, py, xs[k], ys[k], RoutePlanner.START_CLEAR_M)) {
                chosen = k;
            }
        }
        return new double[] {xs[chosen], ys[chosen]};
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(reached || unreachable ? new GetCheckpoint() : this);
    }
}
