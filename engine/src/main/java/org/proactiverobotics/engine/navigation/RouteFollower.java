package org.proactiverobotics.engine.navigation;

import java.util.Locale;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * Follows a route to one goal on the map known so far, the way a rule that drives somewhere holds
 * it: it plans when it has no route, when an occupied cell has appeared on the route ahead, when
 * no waypoint is in sight any more, and every {@value #REPLAN_EVERY} calls; between plans it aims
 * at the goal when the map shows a clear straight way, else at the farthest waypoint in sight
 * within {@value #LOOKAHEAD_M} m of route. The route is a few waypoints kept in plain fields, so
 * it is saved with the rule: a resumed engine follows the route the uninterrupted one did.
 *
 * <p>Told the simulated time, it also watches its progress: when the route's remaining length has
 * not shrunk by {@value #PROGRESS_M} m for {@value #STALL_MS} ms while the robot was driving for it
 * (a gap the planner lets the body through and the collision monitor does not: the robot turns on
 * the spot), it closes the tightest place on the route ahead on its own map ({@link ClosedPlaces}),
 * backs off for {@value #BACK_OFF_MS} ms and plans again round it; when no other way remains the
 * planner finds no route, as for a walled-in goal.
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
    /** The route's remaining length must shrink by this much to count as progress, metres. */
    public static final double PROGRESS_M = 0.1;
    /** No progress for this long while driving for the route is a stall, simulated ms. */
    public static final long STALL_MS = 5_000;
    /** The robot staying within {@value #STAY_M} m of one spot for this long while driving is a stall too, simulated ms. */
    static final long STAY_MS = 4 * STALL_MS;
    /** The spot's radius for {@link #STAY_MS}, metres. */
    static final double STAY_M = 0.5;
    /** After a stall the robot backs off straight for this long, simulated ms. */
    public static final long BACK_OFF_MS = 1_000;
    /** Backing-off speed, as a share of the top speed. */
    static final double BACK_SPEED = 0.3;
    /** The route ahead is searched this far for its tightest place, metres along it. */
    static final double CLOSE_AHEAD_M = 1.0;
    /** Clearances are measured up to this far, metres. */
    static final double CLEARANCE_CAP_M = 0.5;
    /** After this many stalls inside places already closed the follower finds no route any more. */
    public static final int STALLS_INSIDE_LIMIT = 3;
    /**
     * When the places it closed are all that stand between the robot and its goal, they are opened
     * again this many times before the follower finds no route: a stall is not proof that a place
     * is too narrow (a noisy map, a detour the robot was turning through), and the scans taken while
     * backing off may show it wider since.
     */
    public static final int REOPENINGS = 1;

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
        NO_ROUTE,
        /** Backing off after a stall: drive {@link #backOffCommand}. */
        BACK_OFF
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
    /** The places closed after stalls, planned round. */
    private ClosedPlaces closed = new ClosedPlaces();
    /** The smallest remaining length since the last progress, metres, and since when, simulated ms (-1: not watching). */
    private double progressBestM;
    private long progressSinceMs = -1;
    /** The spot the robot has stayed near, metres, and since when, simulated ms. */
    private double stayX;
    private double stayY;
    private long staySinceMs = -1;
    /** Backing off until this simulated time, ms (-1: not backing off). */
    private long backUntilMs = -1;
    /** Stalls with the robot inside a place already closed: it cannot get out of a narrow place. */
    private int stallsInside;
    /** How often the closed places were opened again because they alone blocked the goal. */
    private int reopened;
    /** Whether the last step was told the robot shares its world: closed places are then opened whenever they alone block. */
    private transient boolean shared;

    /** Each leg's length, metres, worked out once per route (hypot is slow and the legs are measured every step). */
    private transient double[] legM;
    /**
     * Per leg of the route, its points {@link #blockedAhead} finds near an occupied cell (null: not
     * yet looked at), for one map at one {@link OccupancyMap#occupancyVersion()} and one room: a leg of
     * tens of metres was looked at again every step (JFR: 8 % of a 100 m floor's mission).
     */
    private transient double[][] nearWalls;
    private transient OccupancyMap nearWallsMap;
    private transient long nearWallsVersion;
    private transient double nearWallsKeepM;
    private transient double targetX;
    private transient double targetY;
    /** Whether the last step planned (a route, or none found): the route may have changed. */
    private transient boolean planned;
    /** Whether the last step closed a place ({@link ClosedPlaces#newestReason()} says why). */
    private transient boolean closedNow;
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
        closedNow = false;
        return route(map, x, y, goalX, goalY, goalReachM, robotRadiusM);
    }

    /**
     * One step that also watches the progress (see the class's description): plans if needed,
     * chooses what to drive at, and after a stall closes the place, backs off and plans round it.
     *
     * @param map          the map known so far
     * @param x            the robot's x, metres
     * @param y            its y, metres
     * @param yawRad       its heading, radians
     * @param goalX        the goal's x, metres
     * @param goalY        its y, metres
     * @param goalReachM   any point this close to the goal will do, metres
     * @param robotRadiusM the robot's radius, metres
     * @param simTimeMs    the simulated time of the pose, ms
     * @param driving      whether the robot drove for this route since the last step (its command won, or the
     *                     collision monitor vetoed it); time spent otherwise (charging, another goal) is no stall
     * @return TARGET, NO_ROUTE, or BACK_OFF ({@link #backOffCommand})
     */
    public Status step(OccupancyMap map, double x, double y, double yawRad, double goalX, double goalY, double goalReachM,
                       double robotRadiusM, long simTimeMs, boolean driving) {
        return step(map, x, y, yawRad, goalX, goalY, goalReachM, robotRadiusM, simTimeMs, driving, false);
    }

    /**
     * One step as {@link #step(OccupancyMap, double, double, double, double, double, double, double, long, boolean)},
     * in a world the robot may share with other robots ({@link SharedWorld}). There a stall is no
     * proof that a place is narrow (another robot stood in it, or Yield held the robot while the
     * watch ran): whenever the places closed are all that stand between the robot and its goal they
     * are opened again, however often, and being boxed in by them opens them too, so that the robot
     * tries the way again instead of standing until its goal is declared unreachable.
     *
     * @param shared whether the robot shares its world with other robots
     * @return TARGET, NO_ROUTE, or BACK_OFF ({@link #backOffCommand})
     */
    public Status step(OccupancyMap map, double x, double y, double yawRad, double goalX, double goalY, double goalReachM,
                       double robotRadiusM, long simTimeMs, boolean driving, boolean shared) {
        closedNow = false;
        this.shared = shared;
        if (shared && stallsInside >= STALLS_INSIDE_LIMIT) {
            // boxed in by its own marks in a shared world: the marks go, the way is tried again
            closed = new ClosedPlaces();
            stallsInside = 0;
            reopened++;
            xs = null;
            restartWatch();
        }
        if (stallsInside >= STALLS_INSIDE_LIMIT) {
            planned = false;
            plansWithoutRoute++;
            return Status.NO_ROUTE; // boxed in a narrow place it cannot leave: no way it can drive
        }
        if (backUntilMs >= 0) {
            if (simTimeMs < backUntilMs && clearBehind(map, x, y, yawRad, robotRadiusM)) {
                planned = false;
                return Status.BACK_OFF;
            }
            backUntilMs = -1;
            xs = null; // plan afresh from where the back-off ended
            restartWatch();
        }
        Status status = route(map, x, y, goalX, goalY, goalReachM, robotRadiusM);
        if (status != Status.TARGET) {
            progressSinceMs = -1;
            staySinceMs = -1;
            return status;
        }
        double remaining = remainingM(x, y, goalX, goalY);
        if (!driving || progressSinceMs < 0 || remaining < progressBestM - PROGRESS_M
                || planned && remaining > progressBestM + PROGRESS_M) {
            // progress, a new longer way, or time not spent on this route: the watch starts again
            progressBestM = remaining;
            progressSinceMs = simTimeMs;
        }
        if (!driving || staySinceMs < 0 || beyond(x - stayX, y - stayY, STAY_M)) {
            stayX = x;
            stayY = y;
            staySinceMs = simTimeMs;
        }
        long noProgressMs = simTimeMs - progressSinceMs;
        if (noProgressMs >= STALL_MS || simTimeMs - staySinceMs >= STAY_MS) {
            if (closed.inside(x, y) && ++stallsInside >= STALLS_INSIDE_LIMIT) {
                xs = null;
                ys = null;
                planned = true;
                plansWithoutRoute++;
                return Status.NO_ROUTE;
            }
            closeAhead(map, x, y, robotRadiusM, Math.max(noProgressMs, simTimeMs - staySinceMs));
            backUntilMs = simTimeMs + BACK_OFF_MS;
            if (clearBehind(map, x, y, yawRad, robotRadiusM)) {
                return Status.BACK_OFF;
            }
            backUntilMs = -1;
            xs = null;
            restartWatch();
            return route(map, x, y, goalX, goalY, goalReachM, robotRadiusM);
        }
        return status;
    }

    /** Starts the progress watch afresh at the next step. */
    private void restartWatch() {
        progressSinceMs = -1;
        staySinceMs = -1;
    }

    /**
     * @param profile the robot's drive
     * @return the command of a step of backing off: straight back at {@value #BACK_SPEED} of the top speed
     */
    public static String backOffCommand(DriveProfile profile) {
        return Steering.drive(-BACK_SPEED * profile.maxSpeedMps(), 0.0, profile);
    }

    /**
     * Whether the robot drove for a scenario's route in the last iteration, for the progress watch's
     * {@code driving}: that scenario's command won, or the obstacle avoidance's did (it amends the
     * command it finds, so its turns are time spent for the route).
     *
     * @param lastDecision the last decision, "scenario command" (null: none yet)
     * @param scenario     the scenario that follows the route
     * @return whether that time counts for the watch
     */
    public static boolean droveFor(String lastDecision, String scenario) {
        return lastDecision != null
                && (lastDecision.startsWith(scenario + " ") || lastDecision.startsWith(ObstacleAvoidanceScenario.NAME + " "));
    }

    /** @return whether the follower gave up: {@value #STALLS_INSIDE_LIMIT} stalls inside places it had closed */
    public boolean boxedIn() {
        return stallsInside >= STALLS_INSIDE_LIMIT;
    }

    /** @return the places closed after stalls (do not change) */
    public ClosedPlaces closed() {
        return closed;
    }

    /** @return whether the last step closed a place: {@link ClosedPlaces#newestReason()} says which and why */
    public boolean closedNow() {
        return closedNow;
    }

    /** Whether backing off 0.15 m straight keeps the body off the map's occupied cells it would come nearer to. */
    private static boolean clearBehind(OccupancyMap map, double x, double y, double yawRad, double robotRadiusM) {
        double keep = robotRadiusM + RoutePlanner.BODY_MARGIN_M;
        for (int q = 1; q <= 10; q++) {
            double back = 0.015 * q;
            if (map.occupiedApproached(x, y, x - back * Math.cos(yawRad), y - back * Math.sin(yawRad), keep)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Closes the tightest place of the route within {@value #CLOSE_AHEAD_M} m ahead (by the map's
     * occupied cells; the middle of the first stretch within a centimetre of the tightest): a disc
     * that reaches its nearest walls, so that the planner's band of cells through it is shut, open
     * only toward the way the route came. With no route, the robot's own spot.
     */
    private void closeAhead(OccupancyMap map, double x, double y, double robotRadiusM, long stalledMs) {
        int samples = 0;
        double[] sx = new double[64];
        double[] sy = new double[64];
        double[] sc = new double[64];
        double[] dirX = new double[64];
        double[] dirY = new double[64];
        if (xs != null) {
            int k = nearest(x, y);
            double px = x;
            double py = y;
            double along = 0;
            double step = OccupancyMap.CELL_M / 2;
            for (int q = k + 1; q < xs.length && along < CLOSE_AHEAD_M; q++) {
                double len = Math.hypot(xs[q] - px, ys[q] - py);
                int n = Math.max(1, (int) Math.ceil(len / step));
                for (int m = 1; m <= n && along + len * m / n <= CLOSE_AHEAD_M && samples < sx.length; m++) {
                    sx[samples] = px + (xs[q] - px) * m / n;
                    sy[samples] = py + (ys[q] - py) * m / n;
                    sc[samples] = clearance(map, sx[samples], sy[samples]);
                    dirX[samples] = xs[q] - px;
                    dirY[samples] = ys[q] - py;
                    samples++;
                }
                along += len;
                px = xs[q];
                py = ys[q];
            }
        }
        if (samples == 0) {
            closeAt(x, y, robotRadiusM, clearance(map, x, y), 1.0, 0.0, stalledMs);
            return;
        }
        double tightest = Double.POSITIVE_INFINITY;
        for (int q = 0; q < samples; q++) {
            tightest = Math.min(tightest, sc[q]);
        }
        int first = 0;
        while (sc[first] > tightest + 0.01) {
            first++;
        }
        int last = first;
        while (last + 1 < samples && sc[last + 1] <= tightest + 0.01) {
            last++;
        }
        int mid = (first + last) / 2;
        closeAt(sx[mid], sy[mid], robotRadiusM, tightest, -dirX[mid], -dirY[mid], stalledMs);
    }

    private void closeAt(double px, double py, double robotRadiusM, double clearM, double backX, double backY, long stalledMs) {
        double radiusM = Math.min(Math.max(clearM, robotRadiusM) + OccupancyMap.CELL_M, 2 * robotRadiusM);
        closed.close(px, py, radiusM, backX, backY, String.format(Locale.ROOT,
                "closed the way at (%.2f, %.2f) on the map, %.2f m from the nearest wall: no progress along the route for %.1f s;"
                        + " backing off and planning round it", px, py, Math.min(clearM, CLEARANCE_CAP_M), stalledMs / 1000.0));
        closedNow = true;
    }

    /** The distance from a point to the nearest occupied cell's centre, metres, capped at {@value #CLEARANCE_CAP_M}. */
    private static double clearance(OccupancyMap map, double px, double py) {
        if (!map.occupiedWithin(px, py, CLEARANCE_CAP_M)) {
            return CLEARANCE_CAP_M;
        }
        double best = CLEARANCE_CAP_M;
        for (int j = OccupancyMap.cell(py - CLEARANCE_CAP_M); j <= OccupancyMap.cell(py + CLEARANCE_CAP_M); j++) {
            for (int i = OccupancyMap.cell(px - CLEARANCE_CAP_M); i <= OccupancyMap.cell(px + CLEARANCE_CAP_M); i++) {
                double d = Math.hypot(OccupancyMap.centre(i) - px, OccupancyMap.centre(j) - py);
                if (d < best && map.get(i, j) == OccupancyMap.OCCUPIED) {
                    best = d;
                }
            }
        }
        return best;
    }

    /** A plan over seen cells first or with unknown cells free, as this follower plans, round the given places (or none). */
    private Route plan(OccupancyMap map, double x, double y, double goalX, double goalY, double goalReachM, double robotRadiusM,
                       ClosedPlaces round) {
        return overSeen ? RoutePlanner.planSeenFirst(map, x, y, goalX, goalY, goalReachM, robotRadiusM, round)
                : RoutePlanner.plan(map, x, y, goalX, goalY, goalReachM, robotRadiusM, round);
    }

    private Status route(OccupancyMap map, double x, double y, double goalX, double goalY, double goalReachM, double robotRadiusM) {
        double sightM = robotRadiusM + RoutePlanner.SIGHT_MARGIN_M;
        int nearest = xs == null ? -1 : nearest(x, y);
        boolean plan = xs == null || ++sincePlan >= REPLAN_EVERY
                || blockedAhead(map, x, y, nearest, robotRadiusM - slackM)
                || !inSight(map, x, y, xs[Math.min(nearest + 1, xs.length - 1)], ys[Math.min(nearest + 1, xs.length - 1)], sightM, seenRoute)
                        && !inSight(map, x, y, xs[nearest], ys[nearest], sightM, seenRoute);
        planned = plan;
        if (plan) {
            sincePlan = 0;
            ClosedPlaces round = closed.isEmpty() ? null : closed;
            Route route = plan(map, x, y, goalX, goalY, goalReachM, robotRadiusM, round);
            if (route == null && round != null && (shared || reopened < REOPENINGS)) {
                Route through = plan(map, x, y, goalX, goalY, goalReachM, robotRadiusM, null);
                if (through != null) { // the closed places alone blocked the way: they are tried once more
                    reopened++;
                    closed = new ClosedPlaces();
                    stallsInside = 0;
                    route = through;
                }
            }
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
            nearWalls = null;
            nearest = 0;
        }
        if (inSight(map, x, y, goalX, goalY, sightM, seenRoute) && !closed.crossed(x, y, goalX, goalY)) {
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
            if (inSight(map, x, y, xs[k], ys[k], sightM, seenRoute) && !closed.crossed(x, y, xs[k], ys[k])) {
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
        double[] legs = legs();
        double keepM = bodyRadiusM + RoutePlanner.BODY_MARGIN_M;
        if (nearWalls == null || nearWallsMap != map || nearWallsVersion != map.occupancyVersion() || nearWallsKeepM != keepM) {
            // the points near walls depend on the route and the occupied cells alone: kept while neither changes (most steps)
            nearWalls = new double[xs.length - 1][];
            nearWallsMap = map;
            nearWallsVersion = map.occupancyVersion();
            nearWallsKeepM = keepM;
        }
        for (int k = nearest; k < xs.length - 1 && checked < CHECK_AHEAD_M; k++) {
            if (nearWalls[k] == null) {
                nearWalls[k] = pointsNearWalls(map, k, legs[k], keepM);
            }
            double[] p = nearWalls[k];
            for (int q = 0; q < p.length; q += 2) {
                if (beyond(p[q] - x, p[q + 1] - y, RoutePlanner.START_CLEAR_M)) {
                    return true;
                }
            }
            checked += legs[k];
        }
        return false;
    }

    /** @return the points of leg k, every half cell, with an occupied cell within {@code keepM}: x, y pairs, metres */
    private double[] pointsNearWalls(OccupancyMap map, int k, double len, double keepM) {
        int n = Math.max(1, (int) Math.ceil(len / (OccupancyMap.CELL_M / 2)));
        double[] found = NONE;
        int count = 0;
        boolean walls = true;
        for (int q = 0; q <= n; q++) {
            double px = xs[k] + (xs[k + 1] - xs[k]) * q / n;
            double py = ys[k] + (ys[k + 1] - ys[k]) * q / n;
            if (q % STRETCH == 0) {
                // a stretch in blocks of the map with no occupied cell holds no point near a wall
                int last = Math.min(n, q + STRETCH - 1);
                double lx = xs[k] + (xs[k + 1] - xs[k]) * last / n;
                double ly = ys[k] + (ys[k + 1] - ys[k]) * last / n;
                if (!map.occupiedBlockIn(Math.min(px, lx) - keepM, Math.min(py, ly) - keepM, Math.max(px, lx) + keepM,
                        Math.max(py, ly) + keepM)) {
                    q = last;
                    continue;
                }
            }
            if (q % PIECE == 0) {
                // a piece of the leg with no occupied cell near it needs no look at each point
                int last = Math.min(n, q + PIECE - 1);
                walls = occupiedNear(map, px, py, xs[k] + (xs[k + 1] - xs[k]) * last / n, ys[k] + (ys[k + 1] - ys[k]) * last / n, keepM);
            }
            if (walls && map.occupiedWithin(px, py, keepM)) {
                if (count == found.length) {
                    found = java.util.Arrays.copyOf(found, Math.max(8, 2 * count));
                }
                found[count++] = px;
                found[count++] = py;
            }
        }
        return count == found.length ? found : java.util.Arrays.copyOf(found, count);
    }

    /** Points along a line are checked in pieces of this many: a piece with no occupied cell near it is passed at once. */
    private static final int PIECE = 16;
    /** A line is first looked at in stretches of this many points (1.6 m), by the map's blocks of 6.4 m. */
    private static final int STRETCH = 4 * PIECE;

    /**
     * @return whether the map may hold an occupied cell within {@code radiusM} of a point between
     *         two points of a line (the box round both); false: none within that of any point between
     */
    private static boolean occupiedNear(OccupancyMap map, double ax, double ay, double bx, double by, double radiusM) {
        return map.occupiedChunkIn(Math.min(ax, bx) - radiusM, Math.min(ay, by) - radiusM, Math.max(ax, bx) + radiusM,
                Math.max(ay, by) + radiusM);
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
        boolean walls = true;
        int clearTo = 0; // the points up to this one lie in blocks of the map with no occupied cell
        for (int k = 1; k <= n; k++) {
            double t = (double) k / n;
            double px = x0 + t * (x1 - x0);
            double py = y0 + t * (y1 - y0);
            if ((k - 1) % PIECE == 0) {
                if (k > clearTo && (k - 1) % STRETCH == 0) {
                    // a stretch far from any wall seen (a floor's goal is tens of metres away across unexplored rooms) at once
                    int last = Math.min(n, k + STRETCH - 1);
                    double tl = (double) last / n;
                    double lx = x0 + tl * (x1 - x0);
                    double ly = y0 + tl * (y1 - y0);
                    if (!map.occupiedBlockIn(Math.min(px, lx) - clearM, Math.min(py, ly) - clearM, Math.max(px, lx) + clearM,
                            Math.max(py, ly) + clearM)) {
                        clearTo = last;
                    }
                }
                if (k <= clearTo && !seenOnly) {
                    k = clearTo;
                    continue;
                }
                // a piece of the line with no occupied cell near it needs no look at each point (on a floor the goal is far)
                double tb = (double) Math.min(n, k + PIECE - 1) / n;
                walls = k > clearTo && occupiedNear(map, px, py, x0 + tb * (x1 - x0), y0 + tb * (y1 - y0), clearM);
            }
            if (walls && (t * len < RoutePlanner.START_CLEAR_M
                    ? map.occupiedApproached(x0, y0, px, py, clearM - NEAR_SLACK_M)
                    : map.occupiedWithin(px, py, clearM))) {
                return false;
            }
            if (seenOnly && map.get(OccupancyMap.cell(px), OccupancyMap.cell(py)) == OccupancyMap.UNKNOWN) {
                return false;
            }
        }
        return true;
    }
}
