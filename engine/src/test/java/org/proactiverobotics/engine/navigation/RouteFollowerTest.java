package org.proactiverobotics.engine.navigation;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.Gson;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.OccupancyMap;

/** Routes on the map known so far: round a wall, saved with the rule, re-planned when a wall appears on them. */
class RouteFollowerTest {

    private static final double RADIUS_M = 0.12;

    /** A wall from (x, y0) to (x, y1), as a scan would mark it. */
    private static void wall(OccupancyMap map, double x, double y0, double y1) {
        for (double y = y0; y <= y1; y += OccupancyMap.CELL_M / 2) {
            map.set(OccupancyMap.cell(x), OccupancyMap.cell(y), OccupancyMap.OCCUPIED);
        }
    }

    @Test
    void aWallAcrossTheWayIsGoneRoundNotThrough() {
        OccupancyMap map = OccupancyMap.empty();
        wall(map, 1.0, -1.0, 0.6);
        RouteFollower follower = new RouteFollower();
        assertThat(follower.step(map, 0, 0, 2, 0, 0.1, RADIUS_M)).isEqualTo(RouteFollower.Status.TARGET);
        assertThat(follower.targetX()).as("not straight at the goal behind the wall").isNotEqualTo(2.0);
        assertThat(follower.targetY()).as("round the wall's open end").isGreaterThan(0.6);
        assertThat(follower.remainingM(0, 0, 2, 0)).isGreaterThan(2.2);
        Route route = RoutePlanner.plan(map, 0, 0, 2, 0, 0.1, RADIUS_M);
        assertThat(route.size()).as("a few waypoints, not a chain of cells").isLessThan(8);
    }

    /**
     * Issue 33: a look along a line tens of metres long passes stretches far from any wall at once;
     * it still finds every occupied cell within the clearance of any of its points, as a look at each
     * point does, wherever along the line (a first, middle or last stretch) the cell lies.
     */
    @Test
    void aLookAlongALongLineFindsEveryWallAsALookAtEachPointDoes() {
        java.util.Random random = new java.util.Random(5);
        OccupancyMap map = OccupancyMap.empty();
        for (int j = -300; j < 300; j++) {
            for (int i = -300; i < 300; i++) {
                map.set(i, j, OccupancyMap.FREE); // seen, for the looks over seen cells only; unknown beyond 15 m
            }
        }
        int blocked = 0;
        for (int trial = 0; trial < 400; trial++) {
            int[][] walls = new int[2][];
            for (int n = 0; n < walls.length; n++) {
                walls[n] = new int[] {random.nextInt(800) - 400, random.nextInt(800) - 400};
                map.set(walls[n][0], walls[n][1], OccupancyMap.OCCUPIED);
            }
            // a line from afar past the first wall, a little to its side, ending anywhere up to as far beyond it
            double wx = OccupancyMap.centre(walls[0][0]) + random.nextGaussian() * 0.2;
            double wy = OccupancyMap.centre(walls[0][1]) + random.nextGaussian() * 0.2;
            double x0 = random.nextDouble() * 40 - 20;
            double y0 = random.nextDouble() * 40 - 20;
            double beyond = random.nextDouble() * 1.2;
            double x1 = wx + (wx - x0) * beyond;
            double y1 = wy + (wy - y0) * beyond;
            double clearM = 0.1 + random.nextDouble() * 0.3;
            boolean seenOnly = trial % 5 == 0;
            boolean expected = inSightPointByPoint(map, x0, y0, x1, y1, clearM, seenOnly);
            assertThat(RouteFollower.inSight(map, x0, y0, x1, y1, clearM, seenOnly)).as("trial %d", trial).isEqualTo(expected);
            blocked += expected ? 0 : 1;
            for (int[] w : walls) {
                map.set(w[0], w[1], OccupancyMap.FREE);
            }
        }
        assertThat(blocked).as("lines a wall blocks, of 400").isBetween(100, 360);
    }

    /** The look at each point, with no piece or stretch passed at once. */
    private static boolean inSightPointByPoint(OccupancyMap map, double x0, double y0, double x1, double y1, double clearM,
                                               boolean seenOnly) {
        double len = Math.hypot(x1 - x0, y1 - y0);
        int n = (int) Math.ceil(len / (OccupancyMap.CELL_M / 2));
        for (int k = 1; k <= n; k++) {
            double t = (double) k / n;
            double px = x0 + t * (x1 - x0);
            double py = y0 + t * (y1 - y0);
            if (t * len < RoutePlanner.START_CLEAR_M
                    ? map.occupiedApproached(x0, y0, px, py, clearM - RouteFollower.NEAR_SLACK_M)
                    : map.occupiedWithin(px, py, clearM)) {
                return false;
            }
            if (seenOnly && map.get(OccupancyMap.cell(px), OccupancyMap.cell(py)) == OccupancyMap.UNKNOWN) {
                return false;
            }
        }
        return true;
    }

    @Test
    void aFollowerSavedAndRestoredFollowsTheSameRoute() {
        OccupancyMap map = OccupancyMap.empty();
        wall(map, 1.0, -1.0, 0.6);
        RouteFollower follower = new RouteFollower();
        follower.step(map, 0, 0, 2, 0, 0.1, RADIUS_M);
        Gson gson = new Gson();
        RouteFollower restored = gson.fromJson(gson.toJson(follower), RouteFollower.class);
        follower.step(map, 0.05, 0.05, 2, 0, 0.1, RADIUS_M);
        restored.step(map, 0.05, 0.05, 2, 0, 0.1, RADIUS_M);
        assertThat(restored.targetX()).isEqualTo(follower.targetX());
        assertThat(restored.targetY()).isEqualTo(follower.targetY());
        assertThat(gson.toJson(restored)).isEqualTo(gson.toJson(follower));
    }

    @Test
    void aWallThatAppearsOnTheRouteMakesItPlanAgain() {
        OccupancyMap map = OccupancyMap.empty();
        RouteFollower follower = new RouteFollower();
        follower.step(map, 0, 0, 3, 0, 0.1, RADIUS_M);
        assertThat(follower.targetX()).as("nothing known: straight at the goal").isEqualTo(3.0);
        wall(map, 1.5, -0.8, 1.0);
        follower.step(map, 0.02, 0, 3, 0, 0.1, RADIUS_M);
        assertThat(follower.targetX()).as("no longer straight at the goal").isNotEqualTo(3.0);
        assertThat(follower.targetY()).as("round the wall's lower end, the nearer").isLessThan(-0.8);
    }

    @Test
    void aGoalInsideAClosedRingHasNoRoute() {
        OccupancyMap map = OccupancyMap.empty();
        for (int a = 0; a < 360; a++) {
            double t = Math.toRadians(a);
            map.set(OccupancyMap.cell(2 + 0.5 * Math.cos(t)), OccupancyMap.cell(0.5 * Math.sin(t)), OccupancyMap.OCCUPIED);
        }
        RouteFollower follower = new RouteFollower();
        assertThat(follower.step(map, 0, 0, 2, 0, 0.1, RADIUS_M)).isEqualTo(RouteFollower.Status.NO_ROUTE);
        assertThat(follower.plansWithoutRoute()).isEqualTo(1);
    }

    @Test
    void thePlannerSeesEveryChangeToTheSameMapWhetherDrawnOrReadBackAsRows() {
        OccupancyMap map = OccupancyMap.empty();
        wall(map, 1.0, -0.6, 1.0);
        Route before = RoutePlanner.plan(map, 0, 0, 2, 0, 0.1, RADIUS_M);
        assertThat(RoutePlanner.plan(map, 0, 0, 2, 0, 0.1, RADIUS_M).lengthM()).as("the same map, the same route")
                .isEqualTo(before.lengthM());
        // the same object, the wall lengthened: a route planned on what the map was would cross it
        OccupancyMap other = OccupancyMap.empty();
        wall(other, 1.0, -2.5, 1.0);
        map.putAll(other.takeChanged());
        Route after = RoutePlanner.plan(map, 0, 0, 2, 0, 0.1, RADIUS_M);
        assertThat(after.lengthM()).as("round the wall's upper end now, the farther").isGreaterThan(before.lengthM() + 0.2);
        // cells cleared again: back to the first route
        for (int j = OccupancyMap.cell(-2.5); j < OccupancyMap.cell(-0.6); j++) {
            map.set(OccupancyMap.cell(1.0), j, OccupancyMap.FREE);
        }
        assertThat(RoutePlanner.plan(map, 0, 0, 2, 0, 0.1, RADIUS_M).lengthM()).isEqualTo(before.lengthM());
    }

    @Test
    void aFollowerOverSeenCellsAimsOnlyAlongSeenCells() {
        OccupancyMap map = OccupancyMap.empty();
        // seen: a band up from the start, across and down to the goal; between, nothing seen
        for (int i = -4; i <= 44; i++) {
            for (int j = -4; j <= 24; j++) {
                if (i <= 4 || i >= 36 || j >= 16) {
                    map.set(i, j, OccupancyMap.FREE);
                }
            }
        }
        double gx = OccupancyMap.centre(40);
        RouteFollower optimistic = new RouteFollower();
        optimistic.step(map, 0.0, 0.0, gx, 0.0, 0.1, RADIUS_M);
        assertThat(optimistic.targetX()).as("unknown cells free: straight at the goal").isEqualTo(gx);
        RouteFollower seen = RouteFollower.overSeenCells();
        assertThat(seen.step(map, 0.0, 0.0, gx, 0.0, 0.1, RADIUS_M)).isEqualTo(RouteFollower.Status.TARGET);
        assertThat(seen.targetY()).as("up the seen band first, not across unseen cells").isGreaterThan(0.5);
        assertThat(seen.remainingM(0.0, 0.0, gx, 0.0)).isGreaterThan(gx + 1.0);
    }

    /** A wall along x = 0 from y = -3 to 3 with a gap of {@code gapM} centred on y = 0, and (optionally) a door at y = 2. */
    private static OccupancyMap gapWall(double gapM, boolean door) {
        OccupancyMap map = OccupancyMap.empty();
        wall(map, 0.0, -3.0, -gapM / 2 - 0.001);
        if (door) {
            wall(map, 0.0, gapM / 2 + 0.001, 1.6);
            wall(map, 0.0, 2.4, 3.0);
        } else {
            wall(map, 0.0, gapM / 2 + 0.001, 3.0);
        }
        return map;
    }

    /**
     * Issue 33: a robot that makes no progress along its route for {@value RouteFollower#STALL_MS} ms
     * (here it stands still in front of a gap the planner lets it through) closes that gap on its
     * map, backs off, and plans round it: through the door when there is one.
     */
    @Test
    void aStallClosesTheGapBacksOffAndPlansRoundIt() {
        OccupancyMap map = gapWall(0.32, true);
        RouteFollower follower = new RouteFollower();
        long t = 0;
        RouteFollower.Status status = follower.step(map, -0.3, 0, 0, 2, 0, 0.1, RADIUS_M, t, true);
        assertThat(status).isEqualTo(RouteFollower.Status.TARGET);
        assertThat(follower.remainingM(-0.3, 0, 2, 0)).as("straight through the gap").isLessThan(2.4);
        while (status == RouteFollower.Status.TARGET && t <= RouteFollower.STALL_MS + 32) {
            t += 32;
            status = follower.step(map, -0.3, 0, 0, 2, 0, 0.1, RADIUS_M, t, true);
        }
        assertThat(status).as("after %d ms without progress", t).isEqualTo(RouteFollower.Status.BACK_OFF);
        assertThat(follower.closedNow()).isTrue();
        assertThat(follower.closed().size()).isEqualTo(1);
        assertThat(follower.closed().newestReason()).startsWith("closed the way at (").contains("no progress along the route for 5.0 s");
        assertThat(follower.closed().inside(0.0, 0.0)).as("the gap itself").isTrue();
        // backing off for a second, then a route round through the door
        long until = t + RouteFollower.BACK_OFF_MS;
        for (t += 32; t < until; t += 32) {
            assertThat(follower.step(map, -0.35, 0, 0, 2, 0, 0.1, RADIUS_M, t, true)).isEqualTo(RouteFollower.Status.BACK_OFF);
        }
        assertThat(follower.step(map, -0.45, 0, 0, 2, 0, 0.1, RADIUS_M, t, true)).isEqualTo(RouteFollower.Status.TARGET);
        assertThat(follower.targetY()).as("toward the door, not the gap").isGreaterThan(0.5);
        assertThat(follower.remainingM(-0.45, 0, 2, 0)).as("round by the door").isGreaterThan(4.0);
    }

    /** The 0.32 m gap in a wall, the whole walled in: the gap is the only way. */
    private static OccupancyMap gapOnlyWay() {
        OccupancyMap map = gapWall(0.32, false);
        wall(map, -3.0, -3.0, 3.0);
        wall(map, 3.0, -3.0, 3.0);
        for (double x = -3.0; x <= 3.0; x += OccupancyMap.CELL_M / 2) {
            map.set(OccupancyMap.cell(x), OccupancyMap.cell(-3.0), OccupancyMap.OCCUPIED);
            map.set(OccupancyMap.cell(x), OccupancyMap.cell(3.0), OccupancyMap.OCCUPIED);
        }
        return map;
    }

    @Test
    void withTheGapClosedAndNoOtherWayThereIsNoRoute() {
        OccupancyMap map = gapOnlyWay();
        RouteFollower follower = new RouteFollower();
        RouteFollower.Status status = RouteFollower.Status.TARGET;
        int backOffs = 0;
        RouteFollower.Status last = status;
        long t;
        long limit = (RouteFollower.REOPENINGS + 1) * (RouteFollower.STALL_MS + RouteFollower.BACK_OFF_MS) + 256;
        for (t = 0; t <= limit && status != RouteFollower.Status.NO_ROUTE; t += 32) {
            status = follower.step(map, -0.3, 0, 0, 2, 0, 0.1, RADIUS_M, t, true);
            if (status == RouteFollower.Status.BACK_OFF && last != RouteFollower.Status.BACK_OFF) {
                backOffs++;
            }
            last = status;
        }
        assertThat(status).isEqualTo(RouteFollower.Status.NO_ROUTE);
        // the closed gap alone blocked the goal: it was tried once more, and closed again after a second stall
        assertThat(backOffs).isEqualTo(RouteFollower.REOPENINGS + 1);
        assertThat(t).isGreaterThan((RouteFollower.REOPENINGS + 1) * RouteFollower.STALL_MS);
        assertThat(follower.closed().describe()).startsWith("(");
    }

    /**
     * The same gap with no other way, in a world shared with other robots: the stall may have been
     * another robot's doing, so the closed gap is opened again each time it alone blocks the goal,
     * and the robot keeps trying it rather than standing until its checkpoint is unreachable.
     */
    @Test
    void inASharedWorldTheClosedGapIsTriedAgainEachTimeItAloneBlocks() {
        OccupancyMap map = gapOnlyWay();
        RouteFollower follower = new RouteFollower();
        RouteFollower.Status last = RouteFollower.Status.TARGET;
        int backOffs = 0;
        int noRoutes = 0;
        long limit = 6 * (RouteFollower.STALL_MS + RouteFollower.BACK_OFF_MS);
        for (long t = 0; t <= limit; t += 32) {
            RouteFollower.Status status = follower.step(map, -0.3, 0, 0, 2, 0, 0.1, RADIUS_M, t, true, true);
            if (status == RouteFollower.Status.BACK_OFF && last != RouteFollower.Status.BACK_OFF) {
                backOffs++;
            }
            noRoutes += status == RouteFollower.Status.NO_ROUTE ? 1 : 0;
            last = status;
        }
        assertThat(backOffs).as("stalled, backed off and tried again, over and over").isGreaterThan(RouteFollower.REOPENINGS + 3);
        assertThat(noRoutes).as("never left without a route by its own marks").isZero();
        assertThat(follower.boxedIn()).isFalse();
    }

    @Test
    void timeNotSpentDrivingForTheRouteIsNoStall() {
        OccupancyMap map = gapWall(0.32, true);
        RouteFollower follower = new RouteFollower();
        for (long t = 0; t < 4 * RouteFollower.STALL_MS; t += 32) {
            assertThat(follower.step(map, -0.3, 0, 0, 2, 0, 0.1, RADIUS_M, t, false)).as("charging, say").isEqualTo(RouteFollower.Status.TARGET);
        }
        assertThat(follower.closed().isEmpty()).isTrue();
    }

    @Test
    void closedPlacesAreSavedWithTheFollowerAndPlannedRoundAfterARestore() {
        OccupancyMap map = gapWall(0.32, true);
        RouteFollower follower = new RouteFollower();
        RouteFollower.Status status = RouteFollower.Status.TARGET;
        long t;
        for (t = 0; status == RouteFollower.Status.TARGET; t += 32) {
            status = follower.step(map, -0.3, 0, 0, 2, 0, 0.1, RADIUS_M, t, true);
        }
        Gson gson = new Gson();
        RouteFollower restored = gson.fromJson(gson.toJson(follower), RouteFollower.class);
        for (long end = t + RouteFollower.BACK_OFF_MS + 64; t < end; t += 32) {
            assertThat(restored.step(map, -0.4, 0, 0, 2, 0, 0.1, RADIUS_M, t, true))
                    .isEqualTo(follower.step(map, -0.4, 0, 0, 2, 0, 0.1, RADIUS_M, t, true));
        }
        assertThat(restored.targetY()).isEqualTo(follower.targetY()).isGreaterThan(0.5);
        assertThat(gson.toJson(restored)).isEqualTo(gson.toJson(follower));
    }
}
