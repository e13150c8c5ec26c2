package org.proactiverobotics.engine.navigation;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * A* on the occupancy map known so far, unknown cells taken as free ({@link #planOverSeen}: blocked), on the robot's footprint:
 * a cell whose centre lies closer than the robot's radius to an occupied cell's centre is
 * blocked, and cells up to {@value #SOFT_ZONE_M} m beyond cost more, so routes keep off walls
 * where they can. The search covers the known map, the robot and the goal, with
 * {@value #MARGIN_M} m around. Cells within {@value #START_CLEAR_M} m of the start are blocked only
 * where the body would be tighter than it is at the start (the robot may already be close to a wall). The cell chain found is shortened to the waypoints
 * a straight drive can join (each leg keeps {@value #SIGHT_MARGIN_M} m more than the robot's radius
 * from occupied cells), so a route is a few points, small enough to save with the rule that follows it.
 * When the usual room finds no route, the plan is tried once more with {@value #TIGHT_SLACK_M} m less.
 */
public final class RoutePlanner {

    /** Cells up to this far beyond the blocked band cost more, metres. */
    static final double SOFT_ZONE_M = 0.2;
    /** Extra cost of a cell at the blocked band's edge, in tenths of a cell's step. */
    static final int SOFT_COST = 40;
    /** Room searched beyond the known map, the robot and the goal, metres. */
    static final double MARGIN_M = 1.0;
    /** A straight drive to a route point keeps this much more than the robot's radius from occupied cells, metres. */
    public static final double SIGHT_MARGIN_M = 0.06;
    /**
     * A cell is blocked closer than the robot's radius plus this to an occupied cell's centre, metres:
     * the room the collision reflex keeps ({@code motion.CollisionReflex#SIDE_MARGIN_M}), so that it never vetoes a route.
     */
    public static final double BODY_MARGIN_M = 0.02;
    /** Cells this close to the start are blocked only where the body would be tighter than at the start, metres. */
    public static final double START_CLEAR_M = 0.25;
    /**
     * Room given up when the usual room finds no route, metres: half a cell, what a route through
     * cell centres loses against a drive between them (a gap whose sides noisy hits drew a little
     * wider is otherwise closed to a planner the collision reflex would let through).
     */
    public static final double TIGHT_SLACK_M = OccupancyMap.CELL_M / 2;

    /** The blocked cells of one plan's area. */
    private static final class Grid {
        final int i0;
        final int j0;
        final int w;
        final int h;
        final boolean[] blocked;
        final boolean[] occupied;
        /** A cell's distance to the nearest occupied cell, metres (capped). */
        final float[] clearance;
        final int[] extra;
        /** Cells never seen, for a plan over seen cells only (null: unknown cells are free). */
        boolean[] unseen;
        /** The robot's radius plus {@value #SIGHT_MARGIN_M} m: a straight drive keeps this far from occupied cells. */
        double sightClearanceM;
        /** The places the follower closed (null: none), and which cells lie in one (null: none in this area). */
        ClosedPlaces closedPlaces;
        boolean[] inClosed;

        Grid(int i0, int j0, int w, int h) {
            this.i0 = i0;
            this.j0 = j0;
            this.w = w;
            this.h = h;
            this.blocked = new boolean[w * h];
            this.occupied = new boolean[w * h];
            this.clearance = new float[w * h];
            this.extra = new int[w * h];
        }

        /** @return whether a straight drive may not cross a cell (map column, row); outside the area counts as free */
        boolean blockedAt(int i, int j, boolean nearStart) {
            int a = i - i0;
            int b = j - j0;
            if (a < 0 || b < 0 || a >= w || b >= h) {
                return false;
            }
            int k = b * w + a;
            return nearStart ? occupied[k] : clearance[k] < sightClearanceM || unseen != null && unseen[k];
        }


        /**
         * @return whether the segment crosses no blocked cell (sampled every half cell); within
         *         {@code clearM} of its start only occupied cells count (the robot may already be close to a wall)
         */
        boolean visible(double x0, double y0, double x1, double y1, double clearM) {
            double len = Math.hypot(x1 - x0, y1 - y0);
            int n = (int) Math.ceil(len / (OccupancyMap.CELL_M / 2));
            for (int k = 1; k <= n; k++) {
                double t = (double) k / n;
                if (blockedAt(OccupancyMap.cell(x0 + t * (x1 - x0)), OccupancyMap.cell(y0 + t * (y1 - y0)), t * len < clearM)) {
                    return false;
                }
            }
            return inClosed == null || !closedPlaces.crossed(x0, y0, x1, y1);
        }
    }

    private RoutePlanner() {
    }

    /**
     * Plans a route with the body's usual room; when there is none, once more with
     * {@value #TIGHT_SLACK_M} m less ({@link Route#slackM()}).
     *
     * @param map           the map known so far
     * @param sx            start x, metres
     * @param sy            start y, metres
     * @param gx            goal x, metres
     * @param gy            goal y, metres
     * @param goalReachM    any cell centre this close to the goal will do, metres
     * @param robotRadiusM  the robot's radius, metres
     * @return the route, or null when none exists even with every unknown cell free and half a cell less room
     */
    public static Route plan(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM, double robotRadiusM) {
        return plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, null);
    }

    /**
     * As {@link #plan(OccupancyMap, double, double, double, double, double, double)}, round the
     * places a follower closed: no route goes deeper into one than its start lies.
     *
     * @param closed the closed places (null: none)
     * @return the route, or null when none exists
     */
    public static Route plan(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM, double robotRadiusM,
                             ClosedPlaces closed) {
        Route route = plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, 0.0, false, closed);
        return route != null ? route : plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, TIGHT_SLACK_M, false, closed);
    }

    /**
     * Plans a route whose cell chain keeps to the cells the rays have seen (unknown cells blocked for
     * the body's centre; its straight legs keep to seen cells too), as {@link #plan} otherwise: a way
     * the rays have shown open, such as the way back to a station the robot came from. Its length is
     * the better bound of the way from above, where {@link #plan}'s, through unknown cells, bounds it from below.
     *
     * @return the route, or null when the seen cells hold none (at once when no cell near the goal was seen)
     */
    public static Route planOverSeen(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                                     double robotRadiusM) {
        return planOverSeen(map, sx, sy, gx, gy, goalReachM, robotRadiusM, null);
    }

    private static Route planOverSeen(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                                      double robotRadiusM, ClosedPlaces closed) {
        if (!seenNear(map, gx, gy, goalReachM)) {
            return null; // no search: a failed one covers every seen cell (the profile put it at 40 % of a mission)
        }
        Route route = plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, 0.0, true, closed);
        return route != null ? route : plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, TIGHT_SLACK_M, true, closed);
    }

    /**
     * A route over the cells the rays have seen where they hold one ({@link #planOverSeen}), else one
     * with unknown cells free ({@link #plan}): a way the robot knows it can drive where there is one.
     *
     * @return the route ({@link Route#overSeen()} says which), or null when neither finds one
     */
    public static Route planSeenFirst(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                                      double robotRadiusM) {
        return planSeenFirst(map, sx, sy, gx, gy, goalReachM, robotRadiusM, null);
    }

    /**
     * As {@link #planSeenFirst(OccupancyMap, double, double, double, double, double, double)}, round the closed places.
     *
     * @param closed the closed places (null: none)
     * @return the route, or null when neither plan finds one
     */
    public static Route planSeenFirst(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                                      double robotRadiusM, ClosedPlaces closed) {
        Route route = planOverSeen(map, sx, sy, gx, gy, goalReachM, robotRadiusM, closed);
        return route != null ? route : plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, closed);
    }

    /** Whether a cell whose centre lies within {@code reachM} of a point (or the point's own cell) has been seen. */
    private static boolean seenNear(OccupancyMap map, double x, double y, double reachM) {
        int r = (int) Math.ceil(reachM / OccupancyMap.CELL_M);
        int ci = OccupancyMap.cell(x);
        int cj = OccupancyMap.cell(y);
        for (int j = cj - r; j <= cj + r; j++) {
            for (int i = ci - r; i <= ci + r; i++) {
                boolean near = i == ci && j == cj
                        || Math.hypot(OccupancyMap.centre(i) - x, OccupancyMap.centre(j) - y) <= reachM;
                if (near && map.get(i, j) == OccupancyMap.FREE) {
                    return true;
                }
            }
        }
        return false;
    }

    private static Route plan(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                              double robotRadiusM, double slackM, boolean seenOnly, ClosedPlaces closed) {
        double c = OccupancyMap.CELL_M;
        int margin = (int) Math.ceil(MARGIN_M / c);
        int si = OccupancyMap.cell(sx);
        int sj = OccupancyMap.cell(sy);
        int gi = OccupancyMap.cell(gx);
        int gj = OccupancyMap.cell(gy);
        int lo_i = Math.min(si, gi);
        int hi_i = Math.max(si, gi);
        int lo_j = Math.min(sj, gj);
        int hi_j = Math.max(sj, gj);
        if (!map.isEmpty()) {
            lo_i = Math.min(lo_i, map.minCell(true));
            lo_j = Math.min(lo_j, map.minCell(false));
            hi_i = Math.max(hi_i, map.maxCellExclusive(true) - 1);
            hi_j = Math.max(hi_j, map.maxCellExclusive(false) - 1);
        }
        Grid g = new Grid(lo_i - margin, lo_j - margin, hi_i - lo_i + 1 + 2 * margin, hi_j - lo_j + 1 + 2 * margin);
        g.sightClearanceM = robotRadiusM + SIGHT_MARGIN_M; // a tight route keeps its cells where they are tight
        int w = g.w;
        int h = g.h;
        int n = w * h;

        // Chamfer distance (3-4, in thirds of a cell) to the nearest occupied cell, capped.
        int cap = (int) Math.ceil((robotRadiusM + BODY_MARGIN_M + SOFT_ZONE_M) / c) * 3 + 4;
        int[] dist = distances(map, g, cap);
        double clear2 = START_CLEAR_M * START_CLEAR_M;
        int startCell = (sj - g.j0) * w + (si - g.i0);
        // near the start a cell is blocked only where the body would be tighter than it is already
        double bodyM = robotRadiusM + BODY_MARGIN_M - slackM;
        double startBlockM = Math.min(bodyM, dist[startCell] / 3.0 * c - OccupancyMap.CELL_M / 2);
        for (int b = 0; b < h; b++) {
            for (int a = 0; a < w; a++) {
                int k = b * w + a;
                double dm = dist[k] / 3.0 * c;
                g.clearance[k] = (float) dm;
                double ox = OccupancyMap.centre(g.i0 + a) - sx;
                double oy = OccupancyMap.centre(g.j0 + b) - sy;
                boolean nearStart = ox * ox + oy * oy <= clear2;
                if (dist[k] == 0 || dm < (nearStart ? startBlockM : bodyM)) {
                    g.blocked[k] = true; // occupied cells stay blocked even next to the start
                    g.occupied[k] = dist[k] == 0;
                } else if (seenOnly && !nearStart && map.get(g.i0 + a, g.j0 + b) == OccupancyMap.UNKNOWN) {
                    g.blocked[k] = true;
                    if (g.unseen == null) {
                        g.unseen = new boolean[n];
                    }
                    g.unseen[k] = true;
                } else if (dm < bodyM + SOFT_ZONE_M) {
                    g.extra[k] = (int) Math.round(SOFT_COST * (1 - Math.max(0, dm - bodyM) / SOFT_ZONE_M));
                }
            }
        }

        if (closed != null && !closed.isEmpty()) {
            markClosed(g, closed);
        }
        boolean[] inClosed = g.inClosed;

        // A* over 8 neighbours, steps 10 and 14, no corner cutting; any cell near enough to the goal ends it.
        int start = (sj - g.j0) * w + (si - g.i0);
        double reach2 = goalReachM * goalReachM;
        int reachTenths = (int) Math.floor(goalReachM / c * 10);
        int[] cost = new int[n];
        Arrays.fill(cost, Integer.MAX_VALUE);
        int[] from = new int[n];
        boolean[] done = new boolean[n];
        long[] heap = new long[1024];
        int size = 0;
        cost[start] = 0;
        from[start] = -1;
        heap[size++] = ((long) heuristic(si, sj, gi, gj, reachTenths) << 32) | start;
        int[] di = {1, -1, 0, 0, 1, 1, -1, -1};
        int[] dj = {0, 0, 1, -1, 1, -1, 1, -1};
        int end = -1;
        while (size > 0) {
            long top = heap[0];
            heap[0] = heap[--size];
            siftDown(heap, size);
            int k = (int) top;
            if (done[k]) {
                continue;
            }
            done[k] = true;
            int a = k % w;
            int b = k / w;
            double ex = OccupancyMap.centre(g.i0 + a) - gx;
            double ey = OccupancyMap.centre(g.j0 + b) - gy;
            if (ex * ex + ey * ey <= reach2 || (g.i0 + a == gi && g.j0 + b == gj)) {
                end = k;
                break;
            }
            for (int d = 0; d < 8; d++) {
                int na = a + di[d];
                int nb = b + dj[d];
                if (na < 0 || nb < 0 || na >= w || nb >= h) {
                    continue;
                }
                int nk = nb * w + na;
                if (g.blocked[nk] || done[nk]) {
                    continue;
                }
                if (inClosed != null && inClosed[nk] && !closed.allows(OccupancyMap.centre(g.i0 + a), OccupancyMap.centre(g.j0 + b),
                        OccupancyMap.centre(g.i0 + na), OccupancyMap.centre(g.j0 + nb))) {
                    continue; // a closed place is left the way the robot came, never entered
                }
                if (d >= 4 && (g.blocked[b * w + na] || g.blocked[nb * w + a])) {
                    continue;
                }
                int nc = cost[k] + (d < 4 ? 10 : 14) + g.extra[nk];
                if (nc < cost[nk]) {
                    cost[nk] = nc;
                    from[nk] = k;
                    long f = nc + (long) heuristic(g.i0 + na, g.j0 + nb, gi, gj, reachTenths);
                    if (size == heap.length) {
                        heap = Arrays.copyOf(heap, size * 2);
                    }
                    heap[size++] = (f << 32) | nk;
                    siftUp(heap, size - 1);
                }
            }
        }
        if (end < 0) {
            return null;
        }
        List<Integer> cells = new ArrayList<>();
        for (int k = end; k >= 0; k = from[k]) {
            cells.add(k);
        }
        int m = cells.size();
        double[] xs = new double[m + 1];
        double[] ys = new double[m + 1];
        xs[0] = sx;
        ys[0] = sy;
        for (int q = 1; q < m; q++) {
            int k = cells.get(m - 1 - q);
            xs[q] = OccupancyMap.centre(g.i0 + k % w);
            ys[q] = OccupancyMap.centre(g.j0 + k / w);
        }
        xs[m] = gx;
        ys[m] = gy;
        return shorten(g, xs, ys, slackM, seenOnly);
    }

    /** Which grid cells lie in a closed place, worked out only over the places' own squares. */
    private static void markClosed(Grid g, ClosedPlaces closed) {
        g.closedPlaces = closed;
        for (int p = 0; p < closed.size(); p++) {
            double r = closed.radius(p);
            int ia = Math.max(g.i0, OccupancyMap.cell(closed.x(p) - r));
            int ib = Math.min(g.i0 + g.w - 1, OccupancyMap.cell(closed.x(p) + r));
            int ja = Math.max(g.j0, OccupancyMap.cell(closed.y(p) - r));
            int jb = Math.min(g.j0 + g.h - 1, OccupancyMap.cell(closed.y(p) + r));
            for (int j = ja; j <= jb; j++) {
                for (int i = ia; i <= ib; i++) {
                    if (Math.hypot(OccupancyMap.centre(i) - closed.x(p), OccupancyMap.centre(j) - closed.y(p)) < r) {
                        if (g.inClosed == null) {
                            g.inClosed = new boolean[g.w * g.h];
                        }
                        g.inClosed[(j - g.j0) * g.w + (i - g.i0)] = true;
                    }
                }
            }
        }
    }

    /** The last distances this thread worked out, for the next plan on the same map and area. */
    private static final ThreadLocal<Distances> LAST_DISTANCES = new ThreadLocal<>();

    /** Chamfer distances of one area of one map, at one version of its occupied cells. */
    private record Distances(WeakReference<OccupancyMap> map, long version, int i0, int j0, int w, int h, int cap, int[] dist) {
        boolean of(OccupancyMap m, Grid g, int capThirds) {
            return map.get() == m && version == m.occupancyVersion() && i0 == g.i0 && j0 == g.j0 && w == g.w && h == g.h
                    && cap == capThirds;
        }
    }

    /**
     * Each grid cell's chamfer distance (3-4, in thirds of a cell) to the nearest occupied cell,
     * capped; the same as the last plan's, not worked out again, when neither the occupied cells
     * nor the area changed (the two sweeps were most of a plan's time, JFR). Read only.
     */
    private static int[] distances(OccupancyMap map, Grid g, int cap) {
        Distances last = LAST_DISTANCES.get();
        if (last != null && last.of(map, g, cap)) {
            return last.dist();
        }
        int w = g.w;
        int h = g.h;
        int[] dist = new int[w * h];
        Arrays.fill(dist, cap);
        // the occupied cells, chunk by chunk (a lookup per grid cell was two thirds of a mission's time)
        map.forEachOccupied((i, j) -> {
            int a = i - g.i0;
            int b = j - g.j0;
            if (a >= 0 && a < w && b >= 0 && b < h) {
                dist[b * w + a] = 0;
            }
        });
        for (int b = 0; b < h; b++) {
            for (int a = 0; a < w; a++) {
                int k = b * w + a;
                int d = dist[k];
                if (a > 0) d = Math.min(d, dist[k - 1] + 3);
                if (b > 0) {
                    d = Math.min(d, dist[k - w] + 3);
                    if (a > 0) d = Math.min(d, dist[k - w - 1] + 4);
                    if (a < w - 1) d = Math.min(d, dist[k - w + 1] + 4);
                }
                dist[k] = d;
            }
        }
        for (int b = h - 1; b >= 0; b--) {
            for (int a = w - 1; a >= 0; a--) {
                int k = b * w + a;
                int d = dist[k];
                if (a < w - 1) d = Math.min(d, dist[k + 1] + 3);
                if (b < h - 1) {
                    d = Math.min(d, dist[k + w] + 3);
                    if (a < w - 1) d = Math.min(d, dist[k + w + 1] + 4);
                    if (a > 0) d = Math.min(d, dist[k + w - 1] + 4);
                }
                dist[k] = d;
            }
        }
        LAST_DISTANCES.set(new Distances(new WeakReference<>(map), map.occupancyVersion(), g.i0, g.j0, w, h, cap, dist));
        return dist;
    }

    /** Keeps only the points a straight drive must pass through: from each kept point, the last one of the chain still in sight. */
    private static Route shorten(Grid g, double[] xs, double[] ys, double slackM, boolean seenOnly) {
        int n = xs.length;
        int[] kept = new int[n];
        int count = 0;
        kept[count++] = 0;
        int at = 0;
        while (at < n - 1) {
            int next = at + 1;
            double clearM = at == 0 ? START_CLEAR_M : 0.0;
            while (next + 1 < n && g.visible(xs[at], ys[at], xs[next + 1], ys[next + 1], clearM)) {
                next++;
            }
            kept[count++] = next;
            at = next;
        }
        double[] rx = new double[count];
        double[] ry = new double[count];
        for (int q = 0; q < count; q++) {
            rx[q] = xs[kept[q]];
            ry[q] = ys[kept[q]];
        }
        return new Route(rx, ry, slackM, seenOnly);
    }

    private static int heuristic(int i, int j, int gi, int gj, int reachTenths) {
        int dx = Math.abs(i - gi);
        int dy = Math.abs(j - gj);
        int octile = 10 * Math.max(dx, dy) + 4 * Math.min(dx, dy);
        return Math.max(0, octile - reachTenths);
    }

    private static void siftUp(long[] heap, int k) {
        long v = heap[k];
        while (k > 0) {
            int p = (k - 1) >>> 1;
            if (heap[p] <= v) {
                break;
            }
            heap[k] = heap[p];
            k = p;
        }
        heap[k] = v;
    }

    private static void siftDown(long[] heap, int size) {
        if (size == 0) {
            return;
        }
        long v = heap[0];
        int k = 0;
        while (true) {
            int l = 2 * k + 1;
            if (l >= size) {
                break;
            }
            int r = l + 1;
            int s = r < size && heap[r] < heap[l] ? r : l;
            if (heap[s] >= v) {
                break;
            }
            heap[k] = heap[s];
            k = s;
        }
        heap[k] = v;
    }
}
