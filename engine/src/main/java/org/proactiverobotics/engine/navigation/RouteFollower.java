package org.proactiverobotics.engine.navigation;

import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * Follows a route to one goal on the map known so far, the way a rule that drives somewhere holds
 * it: it plans when it has no route, when an occupied cell has appeared on the route ahead, when
 * no waypoint is in sight any more, and every {@value #REPLAN_EVERY} calls; between plans it aims
 * at the goal when the map shows a clear straight way, else at the farthest waypoint in sight
 * within {@value #LOOKAHEAD_M} m of route. The route is a few waypoints kept in plain fields, so
 * it is saved with the rule: a resumed engine follows the route the uninterrupted one did.
 */
public final class RouteFollower {

    /** Plan afresh at least this often, calls (the robot may have strayed from a route that still works). */
    public static final int REPLAN_EVERY = 64;
    /** The farthest route point aimed at, metres along the route. */
    public static final double LOOKAHEAD_M = 2.0;
    /** The route is checked for new obstacles this far ahead, metres (beyond, the sensors have seen nothing new). */
    static final double CHECK_AHEAD_M = 3.0;
    /** Near the robot a straight drive may pass this much closer to a wall than elsewhere, metres. */
    static final double NEAR_SLACK_M = RoutePlanner.SIGHT_MARGIN_M - RoutePlanner.BODY_MARGIN_M;

    /** A follower of routes planned with unknown cells free. */
    public RouteFollower() {
    }

    /**
     * @return a follower of routes over the cells the rays have seen where there is one (else with
     *         unknown cells free): a way back the robot knows it can drive, whose length the battery's promise counted
     */
    public static RouteFollower overSeenCells() {
        RouteFollower f = new RouteFollower();
        f.overSeen = true;
        return f;
    }

    /** What one call decided. */
    public enum Status {
        /** A target to drive at. */
        TARGET,
        /** No route: the planner found none this call. */
        NO_ROUTE
    }

    private double[] xs;
    private double[] ys;
    private int sincePlan;
    /** Plans in a row that found no route. */
    private int plansWithoutRoute;
    /** Whether routes keep to the cells the rays have seen ({@link RoutePlanner#planOverSeen}) where they can. */
    private boolean overSeen;
    /** The room the route gives up against the usual clearance, metres ({@link Route#slackM()}). */
    private double slackM;
    /** Whether the route is one over seen cells: then the robot aims only along seen cells too. */
    private boolean seenRoute;

    /** Each leg's length, metres, worked out once per route (hypot is slow and the legs are measured every step). */
    private transient double[] legM;
    private transient double targetX;
    private transient double targetY;
    /** Whether the last step planned (a route, or none found): the route may have changed. */
    private transient boolean planned;
    private static final double[] NONE = new double[0];

    /**
     * One step: plans if needed and chooses what to drive at.
     *
     * @param map          the map known so far
     * @param x            the robot's x, metres
     * @param y            its y, metres
     * @param goalX        the goal's x, metres
     * @param goalY        its y, metres
     * @param goalReachM   any point this close to the goal will do, metres
     * @param robotRadiusM the robot's radius, metres
     * @return TARGET ({@link #targetX()}, {@link #targetY()}), or NO_ROUTE when the planner found none
     */
    public Status step(OccupancyMap map, double x, double y, double goalX, double goalY, double goalReachM, double robotRadiusM) {
        double sightM = robotRadiusM + RoutePlanner.SIGHT_MARGIN_M;
        int nearest = xs == null ? -1 : nearest(x, y);
        boolean plan = xs == null || ++sincePlan >= REPLAN_EVERY
                || blockedAhead(map, x, y, nearest, robotRadiusM - slackM)
                || !inSight(map, x, y, xs[Math.min(nearest + 1, xs.length - 1)], ys[Math.min(nearest + 1, xs.length - 1)], sightM, seenRoute)
                        && !inSight(map, x, y, xs[nearest], ys[nearest], sightM, seenRoute);
        planned = plan;
        if (plan) {
            sincePlan = 0;
            Route route = overSeen ? RoutePlanner.planSeenFirst(map, x, y, goalX, goalY, goalReachM, robotRadiusM)
                    : RoutePlanner.plan(map, x, y, goalX, goalY, goalReachM, robotRadiusM);
            if (route == null) {
                plansWithoutRoute++;
                xs = null;
                ys = null;
                slackM = 0;
                seenRoute = false;
                return Status.NO_ROUTE;
            }
            plansWithoutRoute = 0;
            xs = route.xs();
            ys = route.ys();
            slackM = route.slackM();
            seenRoute = route.overSeen();
            legM = null;
            nearest = 0;
        }
        if (inSight(map, x, y, goalX, goalY, sightM, seenRoute)) {
            targetX = goalX;
            targetY = goalY;
            return Status.TARGET;
        }
        int chosen = Math.min(nearest + 1, xs.length - 1);
        double[] legs = legs();
        double along = 0;
        for (int k = nearest + 1; k < xs.length; k++) {
            along += legs[k - 1];
            if (k > chosen && along > LOOKAHEAD_M) {
                break;
            }
            if (inSight(map, x, y, xs[k], ys[k], sightM, seenRoute)) {
                chosen = k;
            }
        }
        targetX = xs[chosen];
        targetY = ys[chosen];
        return Status.TARGET;
    }

    /** @return the x to drive at, metres (after a TARGET step) */
    public double targetX() {
        return targetX;
    }

    /** @return the y to drive at, metres (after a TARGET step) */
    public double targetY() {
        return targetY;
    }

    /** @return whether the last step planned, so that the route may have changed (or been dropped) */
    public boolean planned() {
        return planned;
    }

    /** @return the route's waypoints' x, metres, from where it was planned to the goal (empty: no route; do not change) */
    public double[] waypointsX() {
        return xs == null ? NONE : xs;
    }

    /** @return the route's waypoints' y, metres (empty: no route; do not change) */
    public double[] waypointsY() {
        return ys == null ? NONE : ys;
    }

    /** @return how many plans in a row found no route */
    public int plansWithoutRoute() {
        return plansWithoutRoute;
    }

    /** @return the route's remaining length from a point, metres (the straight line when there is no route) */
    public double remainingM(double x, double y, double goalX, double goalY) {
        if (xs == null) {
            return Math.hypot(goalX - x, goalY - y);
        }
        int k = nearest(x, y);
        double[] legs = legs();
        double sum = Math.hypot(xs[k] - x, ys[k] - y);
        for (int q = k + 1; q < xs.length; q++) {
            sum += legs[q - 1];
        }
        return sum;
    }

    /** @return the route's leg lengths, metres: leg k joins waypoints k and k + 1 */
    private double[] legs() {
        if (legM == null) {
            legM = new double[xs.length - 1];
            for (int k = 0; k < legM.length; k++) {
                legM[k] = Math.hypot(xs[k + 1] - xs[k], ys[k + 1] - ys[k]);
            }
        }
        return legM;
    }

    /** @return whether hypot(dx, dy) &gt; m, exactly as hypot decides it, with hypot only at a near tie */
    static boolean beyond(double dx, double dy, double m) {
        double d2 = dx * dx + dy * dy;
        double m2 = m * m;
        if (d2 > m2 * (1 + 1e-9)) {
            return true;
        }
        if (d2 < m2 * (1 - 1e-9)) {
            return false;
        }
        return Math.hypot(dx, dy) > m;
    }

    /** The waypoint whose leg onward passes nearest the robot (the last waypoint for none). */
    private int nearest(double x, double y) {
        int best = xs.length - 1;
        double bestD = Double.POSITIVE_INFINITY;
        for (int k = 0; k < xs.length - 1; k++) {
            double d = toSegment(x, y, xs[k], ys[k], xs[k + 1], ys[k + 1]);
            if (d < bestD) {
                bestD = d;
                best = k;
            }
        }
        return best;
    }

    private static double toSegment(double px, double py, double ax, double ay, double bx, double by) {
        double dx = bx - ax;
        double dy = by - ay;
        double len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / len2));
        return Math.hypot(ax + t * dx - px, ay + t * dy - py);
    }

    /**
     * Whether an occupied cell lies within the body's radius (the robot's, less a tight route's slack)
     * plus the planner's margin of the route ahead (the robot's own surroundings aside).
     */
    private boolean blockedAhead(OccupancyMap map, double x, double y, int nearest, double bodyRadiusM) {
        double checked = 0;
        double step = OccupancyMap.CELL_M / 2;
        double[] legs = legs();
        for (int k = nearest; k < xs.length - 1 && checked < CHECK_AHEAD_M; k++) {
            double len = legs[k];
            int n = Math.max(1, (int) Math.ceil(len / step));
            for (int q = 0; q <= n; q++) {
                double px = xs[k] + (xs[k + 1] - xs[k]) * q / n;
                double py = ys[k] + (ys[k + 1] - ys[k]) * q / n;
                if (beyond(px - x, py - y, RoutePlanner.START_CLEAR_M) && map.occupiedWithin(px, py, bodyRadiusM + RoutePlanner.BODY_MARGIN_M)) {
                    return true;
                }
            }
            checked += len;
        }
        return false;
    }

    /**
     * Whether a straight drive from the robot to a point keeps {@code clearM} from every occupied
     * cell; near the robot, where it may already be close to a wall, only cells it would come closer
     * to count, and a little less room will do (as the collision reflex allows).
     */
    static boolean inSight(OccupancyMap map, double x0, double y0, double x1, double y1, double clearM) {
        return inSight(map, x0, y0, x1, y1, clearM, false);
    }

    /** As {@link #inSight(OccupancyMap, double, double, double, double, double)}; with {@code seenOnly}, every cell on the way must have been seen. */
    static boolean inSight(OccupancyMap map, double x0, double y0, double x1, double y1, double clearM, boolean seenOnly) {
        double len = Math.hypot(x1 - x0, y1 - y0);
        int n = (int) Math.ceil(len / (OccupancyMap.CELL_M / 2));
        for (int k = 1; k <= n; k++) {
            double t = (double) k / n;
            double px = x0 + t * (x1 - x0);
            double py = y0 + t * (y1 - y0);
            if (t * len < RoutePlanner.START_CLEAR_M
                    ? map.occupiedApproached(x0, y0, px, py, clearM - NEAR_SLACK_M)
                    : map.occupiedWithin(px, py, clearM)) {
                return false;
            }
            if (seenOnly && map.get(OccupancyMap.cell(px), OccupancyMap.cell(py)) == OccupancyMap.UNKNOWN) {
                return false;
            }
        }
        return true;
    }
}
