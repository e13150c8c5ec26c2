package org.proactiverobotics.engine.navigation;

import java.lang.ref.WeakReference;
import java.util.Arrays;
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

    /**
     * An area of at least this many cells (a floor of about 20 m by 20 m) grows in whole blocks and
     * has its distances updated where cells flipped, not worked out afresh each plan.
     */
    static final int LARGE_CELLS = 160_000;
    /** A large area's bounds are multiples of this many cells. */
    static final int AREA_BLOCK = 64;

    /**
     * A* search's arrays, kept by the thread from plan to plan: a cell's cost and way in count only
     * where its mark is this plan's, so that a plan costs what it searches, not its whole area.
     */
    private static final class Search {
        private static final ThreadLocal<Search> OF_THREAD = ThreadLocal.withInitial(Search::new);
        /**
         * Each cell's mark and cost side by side, {@value #FIELDS} ints (8 bytes) a cell: a 100 m by 100 m
         * floor's 4 million cells were 96 MB at six ints a cell, and the search waited on memory (JFR).
         * The mark holds the plan's stamp above {@link #STAMP_SHIFT} (the mark is this plan's where it is at
         * least {@link #base}), the flags {@link #SEEN}, {@link #SHUT} and {@link #KNOWN}, the step the cell
         * was reached by ({@link #FROM_SHIFT}) and its state ({@link #INFO_SHIFT}).
         */
        int[] cells = new int[0];
        static final int FIELDS = 2;
        static final int MARK = 0;
        static final int COST = 1;
        /** Reached: cost and step valid. */
        static final int SEEN = 1;
        /** Done (taken off the open list). */
        static final int SHUT = 2;
        /** State worked out. */
        static final int KNOWN = 4;
        /** The index of the step (of the eight) that reached the cell, {@link #START} at the start, 4 bits. */
        static final int FROM_SHIFT = 3;
        static final int FROM_BITS = 15 << FROM_SHIFT;
        static final int START = 8;
        /** The state plus one: 0 blocked, else the extra cost plus one (at most {@value #SOFT_COST} + 1), 6 bits. */
        static final int INFO_SHIFT = 7;
        static final int STAMP_SHIFT = 13;
        /** The largest stamp that keeps a mark positive; then the marks are cleared and the stamps start again. */
        static final int MAX_STAMP = (1 << (31 - STAMP_SHIFT)) - 1;
        int stamp;
        /** This plan's stamp shifted into place: the least mark of this plan. */
        int base;
        /** The open cells' keys (f, then on a large area the heuristic, else the cell) and, at the same places, the cells. */
        long[] heap = new long[1024];
        int[] heapCell = new int[1024];
        /** On a large area, the open cells whose f equals the cell being expanded's, newest on top. */
        int[] level = new int[1024];
        /** The route's chain of cells, goal first. */
        int[] chain = new int[1024];

        /**
         * @return a cell's state (column a, row b of the area, index k): -1 when blocked, else its extra
         *         cost; worked out once per plan (the search asks for a cell up to a dozen times)
         */
        int info(Grid g, int k, int a, int b) {
            int at = k * FIELDS + MARK;
            int mark = Math.max(cells[at], base);
            if ((mark & KNOWN) == 0) {
                mark |= KNOWN | (g.blocked(a, b) ? 0 : g.extra(a, b) + 1) << INFO_SHIFT;
                cells[at] = mark;
            }
            return (mark >>> INFO_SHIFT & 63) - 1;
        }

        /** @return this thread's arrays, large enough for an area of n cells, with a fresh stamp */
        static Search forArea(int n) {
            Search s = OF_THREAD.get();
            if (s.cells.length < (long) n * FIELDS) {
                // with room to grow: a floor's area grows as it is explored, and each new array was tens of megabytes
                long size = Math.max((long) n * FIELDS, s.cells.length + s.cells.length / 2L);
                s.cells = new int[(int) Math.min(size, Integer.MAX_VALUE - 8 - (Integer.MAX_VALUE - 8) % FIELDS)];
                s.stamp = 0;
            } else if (s.stamp == MAX_STAMP) {
                Arrays.fill(s.cells, 0);
                s.stamp = 0;
            }
            s.stamp++;
            s.base = s.stamp << STAMP_SHIFT;
            return s;
        }
    }

    /**
     * One plan's area: which cells are blocked and what they cost, worked out from the distances
     * when the search asks (a large floor's plan touches a small part of its area).
     */
    private static final class Grid {
        final int i0;
        final int j0;
        final int w;
        final int h;
        /** The chamfer distances to the nearest occupied cell (thirds of a cell, capped), over this area or one round the map. */
        Distances field;
        /** Whether {@link #field} covers exactly this area (then a cell's index is its index there too). */
        boolean sameArea;
        /** The map, for a plan over seen cells only (null: unknown cells are free). */
        OccupancyMap seenOnlyMap;
        /** The map the distances were worked out from. */
        OccupancyMap map;
        double sx;
        double sy;
        /** A cell is blocked closer than this to an occupied cell, metres; near the start, closer than {@link #startBlockM}. */
        double bodyM;
        double startBlockM;
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
        }

        /** @return a cell's chamfer distance to the nearest occupied cell, thirds of a cell (capped) */
        int d(int k) {
            if (sameArea) {
                return field.at(k);
            }
            int a = i0 + k % w - field.i0();
            int b = j0 + k / w - field.j0();
            return a < 0 || b < 0 || a >= field.w() || b >= field.h() ? field.cap() : field.at(b * field.w() + a);
        }

        /** @return whether a cell's centre lies within {@value #START_CLEAR_M} m of the start */
        boolean nearStart(int k) {
            double ox = OccupancyMap.centre(i0 + k % w) - sx;
            double oy = OccupancyMap.centre(j0 + k / w) - sy;
            return ox * ox + oy * oy <= START_CLEAR_M * START_CLEAR_M;
        }

        /** @return whether the body's centre may not enter a cell (column and row in the area): too near an occupied cell, or (over seen cells only) never seen */
        boolean blocked(int a, int b) {
            double ox = OccupancyMap.centre(i0 + a) - sx;
            double oy = OccupancyMap.centre(j0 + b) - sy;
            boolean nearStart = ox * ox + oy * oy <= START_CLEAR_M * START_CLEAR_M;
            int d = sameArea ? field.at(b * w + a) : dAt(i0 + a, j0 + b);
            if (d == 0 || d / 3.0 * OccupancyMap.CELL_M < (nearStart ? startBlockM : bodyM)) {
                return true; // occupied cells stay blocked even next to the start
            }
            return seenOnlyMap != null && !nearStart && seenOnlyMap.get(i0 + a, j0 + b) == OccupancyMap.UNKNOWN;
        }

        /** @return the extra cost of an unblocked cell (column and row in the area) near the blocked band, tenths of a cell's step */
        int extra(int a, int b) {
            double dm = (sameArea ? field.at(b * w + a) : dAt(i0 + a, j0 + b)) / 3.0 * OccupancyMap.CELL_M;
            return dm < bodyM + SOFT_ZONE_M ? (int) Math.round(SOFT_COST * (1 - Math.max(0, dm - bodyM) / SOFT_ZONE_M)) : 0;
        }

        private boolean unseen(int k, boolean nearStart) {
            return seenOnlyMap != null && !nearStart && seenOnlyMap.get(i0 + k % w, j0 + k / w) == OccupancyMap.UNKNOWN;
        }

        /** @return whether a straight drive may not cross a cell (map column, row); outside the area counts as free */
        boolean blockedAt(int i, int j, boolean nearStart) {
            int a = i - i0;
            int b = j - j0;
            if (a < 0 || b < 0 || a >= w || b >= h) {
                return false;
            }
            int k = b * w + a;
            int d = sameArea ? field.at(k) : dAt(i, j);
            // a cell the body may not enter is nearer a wall than a straight drive keeps: the clearance decides
            return nearStart ? d == 0 : (float) (d / 3.0 * OccupancyMap.CELL_M) < sightClearanceM || unseen(k, nearStart(k));
        }

        /**
         * @return whether samples ka to kb (of n) of a segment lie where the map's blocks hold no occupied
         *         cell within far more than {@link #sightClearanceM} (the chamfer distance is at least 0.94 of
         *         the straight one, and a sample lies anywhere in its cell): none of them is then blocked
         */
        boolean clearStretch(double x0, double y0, double x1, double y1, int ka, int kb, int n) {
            double ta = (double) ka / n;
            double tb = (double) kb / n;
            double ax = x0 + ta * (x1 - x0);
            double ay = y0 + ta * (y1 - y0);
            double bx = x0 + tb * (x1 - x0);
            double by = y0 + tb * (y1 - y0);
            double m = sightClearanceM * 1.1 + 2 * OccupancyMap.CELL_M;
            return !map.occupiedBlockIn(Math.min(ax, bx) - m, Math.min(ay, by) - m, Math.max(ax, bx) + m, Math.max(ay, by) + m);
        }

        /** @return the chamfer distance of the cell at map column i, row j, thirds of a cell (capped) */
        private int dAt(int i, int j) {
            int a = i - field.i0();
            int b = j - field.j0();
            return a < 0 || b < 0 || a >= field.w() || b >= field.h() ? field.cap() : field.at(b * field.w() + a);
        }


        /**
         * @return whether the segment crosses no blocked cell (sampled every half cell); within
         *         {@code clearM} of its start only occupied cells count (the robot may already be close to a wall)
         */
        boolean visible(double x0, double y0, double x1, double y1, double clearM) {
            double len = Math.hypot(x1 - x0, y1 - y0);
            int n = (int) Math.ceil(len / (OccupancyMap.CELL_M / 2));
            for (int k = 1; k <= n; k++) {
                if (seenOnlyMap == null && (k - 1) % STRETCH == 0 && clearStretch(x0, y0, x1, y1, k, Math.min(n, k + STRETCH - 1), n)) {
                    k += STRETCH - 1;
                    continue;
                }
                double t = (double) k / n;
                if (blockedAt(OccupancyMap.cell(x0 + t * (x1 - x0)), OccupancyMap.cell(y0 + t * (y1 - y0)), t * len < clearM)) {
                    return false;
                }
            }
            return inClosed == null || !closedPlaces.crossed(x0, y0, x1, y1);
        }
    }

    /** Samples of a straight drive looked at at once by the map's blocks ({@code Grid.clearStretch}): 1.6 m. */
    static final int STRETCH = 64;

    /**
     * The heuristic's weight in a plan whose length need only bound the way from above (the
     * battery's way back): its route is at most this many times the shortest.
     */
    static final double BOUND_WEIGHT = 1.5;
    /**
     * A weighted way is taken up to this share over its bound: the bound is no exact figure (the
     * distance driven is measured pose to pose, a route's length runs through cell centres and
     * keeps off walls), and the shortest way itself often came out just over it; each search for
     * it then opened 60 000 to 280 000 cells on a 100 m by 100 m floor (27 of its 90 weighted
     * plans were over their bound, most by under 1 %, the weighted way within 1.5 % of the shortest).
     */
    static final double BOUND_SLACK = 0.02;

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
        return plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, closed, false);
    }

    /** As the public plan; {@code weighted}: with the heuristic weighted by {@value #BOUND_WEIGHT} on a large area. */
    private static Route plan(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM, double robotRadiusM,
                              ClosedPlaces closed, boolean weighted) {
        Route route = plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, 0.0, false, closed, weighted);
        return route != null ? route : plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, TIGHT_SLACK_M, false, closed, weighted);
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
        return planOverSeen(map, sx, sy, gx, gy, goalReachM, robotRadiusM, null, false);
    }

    private static Route planOverSeen(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                                      double robotRadiusM, ClosedPlaces closed, boolean weighted) {
        if (!seenNear(map, gx, gy, goalReachM)) {
            return null; // no search: a failed one covers every seen cell (the profile put it at 40 % of a mission)
        }
        Route route = plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, 0.0, true, closed, weighted);
        return route != null ? route : plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, TIGHT_SLACK_M, true, closed, weighted);
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
        return planSeenFirst(map, sx, sy, gx, gy, goalReachM, robotRadiusM, closed, false);
    }

    private static Route planSeenFirst(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                                       double robotRadiusM, ClosedPlaces closed, boolean weighted) {
        Route route = planOverSeen(map, sx, sy, gx, gy, goalReachM, robotRadiusM, closed, weighted);
        return route != null ? route : plan(map, sx, sy, gx, gy, goalReachM, robotRadiusM, closed, weighted);
    }

    /**
     * As {@link #planSeenFirst(OccupancyMap, double, double, double, double, double, double)}, for a
     * way whose length need only bound it from above and is known to be at most {@code boundM} (the
     * battery's way back: its last plan plus what was driven since): on a large area (at least
     * {@value #LARGE_CELLS} cells) the search's heuristic is first weighted by {@value #BOUND_WEIGHT},
     * and its route is taken when it is no longer than {@code boundM} plus {@value #BOUND_SLACK} of it
     * ({@link #BOUND_SLACK}); else, and on a smaller area,
     * the shortest route. A shortest-route search across a floor opens every cell as promising as
     * the way round the walls (JFR: 133 000 cells a plan on a 100 m by 100 m floor, most of a step's
     * time); the weighted one heads for the goal and opens a tenth of them.
     *
     * @param boundM what the way is known to be at most, metres
     * @return the route, or null when neither plan finds one
     */
    public static Route planSeenFirstBounded(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                                             double robotRadiusM, double boundM) {
        if (largeArea(map, sx, sy, gx, gy)) {
            Route weighted = planSeenFirst(map, sx, sy, gx, gy, goalReachM, robotRadiusM, null, true);
            if (weighted != null && weighted.lengthM() <= boundM * (1 + BOUND_SLACK)) {
                return weighted;
            }
        }
        return planSeenFirst(map, sx, sy, gx, gy, goalReachM, robotRadiusM, null, false);
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

    /** @return a plan's area: the known map, the start and the goal, with {@value #MARGIN_M} m around */
    private static Grid area(OccupancyMap map, double sx, double sy, double gx, double gy) {
        int margin = (int) Math.ceil(MARGIN_M / OccupancyMap.CELL_M);
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
        return new Grid(lo_i - margin, lo_j - margin, hi_i - lo_i + 1 + 2 * margin, hi_j - lo_j + 1 + 2 * margin);
    }

    /** @return whether a plan between two points covers a large area (at least {@value #LARGE_CELLS} cells) */
    private static boolean largeArea(OccupancyMap map, double sx, double sy, double gx, double gy) {
        Grid g = area(map, sx, sy, gx, gy);
        return (long) g.w * g.h >= LARGE_CELLS;
    }

    private static Route plan(OccupancyMap map, double sx, double sy, double gx, double gy, double goalReachM,
                              double robotRadiusM, double slackM, boolean seenOnly, ClosedPlaces closed, boolean weighted) {
        double c = OccupancyMap.CELL_M;
        int margin = (int) Math.ceil(MARGIN_M / c);
        int si = OccupancyMap.cell(sx);
        int sj = OccupancyMap.cell(sy);
        int gi = OccupancyMap.cell(gx);
        int gj = OccupancyMap.cell(gy);
        Grid g = area(map, sx, sy, gx, gy);
        g.sightClearanceM = robotRadiusM + SIGHT_MARGIN_M; // a tight route keeps its cells where they are tight
        int w = g.w;
        int h = g.h;
        int n = w * h;

        // Chamfer distance (3-4, in thirds of a cell) to the nearest occupied cell, capped.
        int cap = (int) Math.ceil((robotRadiusM + BODY_MARGIN_M + SOFT_ZONE_M) / c) * 3 + 4;
        Grid fieldArea = g;
        if ((long) w * h >= LARGE_CELLS && !map.isEmpty()) {
            // a floor's distances are kept over the map, grown in whole blocks as it is explored, wherever start and goal lie
            int lo = Math.floorDiv(map.minCell(true) - margin, AREA_BLOCK) * AREA_BLOCK;
            int lj = Math.floorDiv(map.minCell(false) - margin, AREA_BLOCK) * AREA_BLOCK;
            int hi = Math.floorDiv(map.maxCellExclusive(true) - 1 + margin, AREA_BLOCK) * AREA_BLOCK + AREA_BLOCK;
            int hj = Math.floorDiv(map.maxCellExclusive(false) - 1 + margin, AREA_BLOCK) * AREA_BLOCK + AREA_BLOCK;
            fieldArea = new Grid(lo, lj, hi - lo, hj - lj);
        }
        g.field = distances(map, fieldArea, cap);
        g.sameArea = fieldArea == g;
        int startCell = (sj - g.j0) * w + (si - g.i0);
        // near the start a cell is blocked only where the body would be tighter than it is already
        g.sx = sx;
        g.sy = sy;
        g.bodyM = robotRadiusM + BODY_MARGIN_M - slackM;
        g.startBlockM = Math.min(g.bodyM, g.d(startCell) / 3.0 * c - OccupancyMap.CELL_M / 2);
        g.seenOnlyMap = seenOnly ? map : null;
        g.map = map;

        if (closed != null && !closed.isEmpty()) {
            markClosed(g, closed);
        }
        boolean[] inClosed = g.inClosed;
        // a weighted heuristic, on a large area only: each cell's estimate of the way on, tenths of a cell's step
        double weight = weighted && (long) n >= LARGE_CELLS ? BOUND_WEIGHT : 1.0;

        // A* over 8 neighbours, steps 10 and 14, no corner cutting; any cell near enough to the goal ends it.
        int start = (sj - g.j0) * w + (si - g.i0);
        double reach2 = goalReachM * goalReachM;
        int reachTenths = (int) Math.floor(goalReachM / c * 10);
        Search search = Search.forArea(n);
        int[] node = search.cells;
        final int fields = Search.FIELDS;
        final int base = search.base;
        long[] heap = search.heap;
        int[] heapCell = search.heapCell;
        // on a floor, of the cells equally promising the one nearest the goal first: else A* opens every cell of the
        // equal-cost band between start and goal where unknown cells lie (JFR: most of a floor's time); elsewhere by index.
        // A neighbour as promising as the cell it came from goes on a stack, not the heap (the heap's sifting was a quarter of a plan)
        boolean deepestFirst = (long) n >= LARGE_CELLS;
        int[] level = search.level;
        int levelSize = 0;
        int size = 0;
        node[start * fields + Search.COST] = 0;
        node[start * fields + Search.MARK] = base | Search.SEEN | Search.START << Search.FROM_SHIFT;
        int startH = weighted(heuristic(si, sj, gi, gj, reachTenths), weight);
        heap[size] = ((long) startH << 32) | (deepestFirst ? startH : start);
        heapCell[size++] = start;
        int[] di = {1, -1, 0, 0, 1, 1, -1, -1};
        int[] dj = {0, 0, 1, -1, 1, -1, 1, -1};
        int end = -1;
        while (size > 0 || levelSize > 0) {
            int k;
            if (levelSize > 0) {
                k = level[--levelSize];
            } else {
                k = heapCell[0];
                size--;
                heap[0] = heap[size];
                heapCell[0] = heapCell[size];
                siftDown(heap, heapCell, size);
            }
            int markK = node[k * fields + Search.MARK]; // this plan's: the cell was reached
            if ((markK & Search.SHUT) != 0) {
                continue;
            }
            node[k * fields + Search.MARK] = markK | Search.SHUT;
            int costK = node[k * fields + Search.COST];
            int a = k % w;
            int b = k / w;
            long fk = deepestFirst ? costK + (long) weighted(heuristic(g.i0 + a, g.j0 + b, gi, gj, reachTenths), weight) : -1;
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
                int at = nk * fields;
                int mark = node[at + Search.MARK];
                if (mark >= base && (mark & Search.SHUT) != 0) {
                    continue;
                }
                int extra = search.info(g, nk, na, nb);
                if (extra < 0) {
                    continue;
                }
                if (inClosed != null && inClosed[nk] && !closed.allows(OccupancyMap.centre(g.i0 + a), OccupancyMap.centre(g.j0 + b),
                        OccupancyMap.centre(g.i0 + na), OccupancyMap.centre(g.j0 + nb))) {
                    continue; // a closed place is left the way the robot came, never entered
                }
                if (d >= 4 && (search.info(g, b * w + na, na, b) < 0 || search.info(g, nb * w + a, a, nb) < 0)) {
                    continue;
                }
                int nc = costK + (d < 4 ? 10 : 14) + extra;
                mark = node[at + Search.MARK]; // this plan's now: its state is known
                if ((mark & Search.SEEN) == 0 || nc < node[at + Search.COST]) {
                    node[at + Search.MARK] = mark & ~Search.FROM_BITS | Search.SEEN | d << Search.FROM_SHIFT;
                    node[at + Search.COST] = nc;
                    int hn = weighted(heuristic(g.i0 + na, g.j0 + nb, gi, gj, reachTenths), weight);
                    long f = nc + (long) hn;
                    if (f == fk) {
                        if (levelSize == level.length) {
                            level = Arrays.copyOf(level, levelSize * 2);
                        }
                        level[levelSize++] = nk;
                        continue;
                    }
                    if (size == heap.length) {
                        heap = Arrays.copyOf(heap, size * 2);
                        heapCell = Arrays.copyOf(heapCell, size * 2);
                    }
                    heap[size] = (f << 32) | (deepestFirst ? hn : nk);
                    heapCell[size++] = nk;
                    siftUp(heap, heapCell, size - 1);
                }
            }
        }
        search.heap = heap;
        search.heapCell = heapCell;
        search.level = level;
        if (end < 0) {
            return null;
        }
        // the chain back from the goal, each cell's step undone (an int array kept by the thread, no boxed list)
        int[] chain = search.chain;
        int m = 0;
        for (int k = end; ; ) {
            if (m == chain.length) {
                chain = Arrays.copyOf(chain, m * 2);
            }
            chain[m++] = k;
            int from = node[k * fields + Search.MARK] >>> Search.FROM_SHIFT & 15;
            if (from == Search.START) {
                break;
            }
            k -= dj[from] * w + di[from];
        }
        search.chain = chain;
        double[] xs = new double[m + 1];
        double[] ys = new double[m + 1];
        xs[0] = sx;
        ys[0] = sy;
        for (int q = 1; q < m; q++) {
            int k = chain[m - 1 - q];
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

    /** The largest cap kept in a byte a cell (a robot's radius up to 3.9 m). */
    static final int BYTE_CAP = 255;

    /**
     * Chamfer distances of one area of one map, at one version of its occupied cells: on a large area
     * whose cap allows, a byte a cell ({@code bytes}, read unsigned), else an int ({@code dist}); the other null.
     */
    private record Distances(WeakReference<OccupancyMap> map, long version, int i0, int j0, int w, int h, int cap, int[] dist,
                             byte[] bytes) {
        boolean of(OccupancyMap m, Grid g, int capThirds) {
            return map.get() == m && version == m.occupancyVersion() && i0 == g.i0 && j0 == g.j0 && w == g.w && h == g.h
                    && cap == capThirds;
        }

        /** @return the distance of the cell at index k of the area, thirds of a cell */
        int at(int k) {
            return bytes != null ? bytes[k] & 0xFF : dist[k];
        }

        void set(int k, int d) {
            if (bytes != null) {
                bytes[k] = (byte) d;
            } else {
                dist[k] = d;
            }
        }

        /**
         * @return whether an area's distances are kept a byte a cell: a floor's grew with the map, and each
         *         new copy of its 4 million ints was most of the distances' time (a small area's stay ints, as swept)
         */
        static boolean inBytes(Grid g, int cap) {
            return (long) g.w * g.h >= LARGE_CELLS && cap <= BYTE_CAP;
        }
    }

    /**
     * Each grid cell's chamfer distance (3-4, in thirds of a cell) to the nearest occupied cell,
     * capped; the same as the last plan's, not worked out again, when neither the occupied cells
     * nor the area changed (the two sweeps were most of a plan's time, JFR); on a large area,
     * updated where cells flipped ({@link #updated}). Read only.
     */
    private static Distances distances(OccupancyMap map, Grid g, int cap) {
        Distances last = LAST_DISTANCES.get();
        if (last != null && last.of(map, g, cap)) {
            return last;
        }
        if ((long) g.w * g.h >= LARGE_CELLS && last != null && last.map().get() == map && last.cap() == cap) {
            Distances now = updated(map, g, cap, last);
            if (now != null) {
                LAST_DISTANCES.set(now);
                return now;
            }
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
        sweep(dist, w, h);
        byte[] bytes = null;
        if (Distances.inBytes(g, cap)) {
            bytes = new byte[w * h];
            for (int k = 0; k < bytes.length; k++) {
                bytes[k] = (byte) dist[k];
            }
        }
        Distances now = new Distances(new WeakReference<>(map), map.occupancyVersion(), g.i0, g.j0, w, h, cap,
                bytes == null ? dist : null, bytes);
        LAST_DISTANCES.set(now);
        return now;
    }

    /**
     * The last distances carried over to this area and worked out again only round the cells whose
     * occupancy flipped since: within a square of the cap's reach about them, from the occupied
     * cells within twice that (the chamfer distance there is exact: the occupied cells it is taken
     * from lie in the square's margin, and a chamfer path between two cells keeps to their bounding
     * box). Null when the map no longer knows what flipped, or so much did that a whole sweep is cheaper,
     * or the last ones were kept otherwise (ints, a byte a cell) than this area's are.
     */
    private static Distances updated(OccupancyMap map, Grid g, int cap, Distances last) {
        int w = g.w;
        int h = g.h;
        int[] box = {Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE};
        if (!map.forEachFlipSince(last.version(), (i, j) -> {
            box[0] = Math.min(box[0], i);
            box[1] = Math.min(box[1], j);
            box[2] = Math.max(box[2], i);
            box[3] = Math.max(box[3], j);
        })) {
            return null;
        }
        int reach = (cap + 2) / 3; // cells farther than this from every occupied cell are at the cap
        int pa0 = Math.max(g.i0, box[0] - reach);
        int pb0 = Math.max(g.j0, box[1] - reach);
        int pa1 = Math.min(g.i0 + w - 1, box[2] + reach);
        int pb1 = Math.min(g.j0 + h - 1, box[3] + reach);
        if (box[0] != Integer.MAX_VALUE && (long) (pa1 - pa0 + 1) * (pb1 - pb0 + 1) * 4 > (long) w * h) {
            return null;
        }
        boolean inBytes = Distances.inBytes(g, cap);
        if (inBytes != (last.bytes() != null)) {
            return null;
        }
        Distances now;
        if (last.i0() == g.i0 && last.j0() == g.j0 && last.w() == w && last.h() == h) {
            // updated in place: the last plan's grid is gone
            now = new Distances(last.map(), map.occupancyVersion(), g.i0, g.j0, w, h, cap, last.dist(), last.bytes());
        } else {
            // every occupied cell lies a metre inside both areas: a cell outside the old one is at the cap
            Object from = inBytes ? last.bytes() : last.dist();
            Object to;
            if (inBytes) {
                byte[] bytes = new byte[w * h];
                Arrays.fill(bytes, (byte) cap);
                to = bytes;
                now = new Distances(last.map(), map.occupancyVersion(), g.i0, g.j0, w, h, cap, null, bytes);
            } else {
                int[] dist = new int[w * h];
                Arrays.fill(dist, cap);
                to = dist;
                now = new Distances(last.map(), map.occupancyVersion(), g.i0, g.j0, w, h, cap, dist, null);
            }
            int a0 = Math.max(g.i0, last.i0());
            int a1 = Math.min(g.i0 + w, last.i0() + last.w());
            for (int j = Math.max(g.j0, last.j0()); j < Math.min(g.j0 + h, last.j0() + last.h()) && a0 < a1; j++) {
                System.arraycopy(from, (j - last.j0()) * last.w() + a0 - last.i0(), to, (j - g.j0) * w + a0 - g.i0, a1 - a0);
            }
        }
        if (box[0] == Integer.MAX_VALUE) {
            return now;
        }
        // the square with a margin of the reach, swept as the whole area is
        int ea0 = Math.max(g.i0, pa0 - reach);
        int eb0 = Math.max(g.j0, pb0 - reach);
        int ew = Math.min(g.i0 + w - 1, pa1 + reach) - ea0 + 1;
        int eh = Math.min(g.j0 + h - 1, pb1 + reach) - eb0 + 1;
        int[] d = new int[ew * eh];
        for (int b = 0; b < eh; b++) {
            for (int a = 0; a < ew; a++) {
                d[b * ew + a] = map.get(ea0 + a, eb0 + b) == OccupancyMap.OCCUPIED ? 0 : cap;
            }
        }
        sweep(d, ew, eh);
        for (int j = pb0; j <= pb1; j++) {
            for (int i = pa0; i <= pa1; i++) {
                now.set((j - g.j0) * w + i - g.i0, d[(j - eb0) * ew + i - ea0]);
            }
        }
        return now;
    }

    /** The two chamfer sweeps (3-4) over an area whose occupied cells are 0 and others the cap. */
    private static void sweep(int[] dist, int w, int h) {
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
    }

    /** Keeps only the points a straight drive must pass through: from each kept point, the last one of the chain still in sight. */
    private static Route shorten(Grid g, double[] xs, double[] ys, double slackM, boolean seenOnly) {
        int n = xs.length;
        int[] kept = new int[n];
        int count = 0;
        kept[count++] = 0;
        int at = 0;
        boolean large = (long) g.w * g.h >= LARGE_CELLS;
        while (at < n - 1) {
            int next = at + 1;
            double clearM = at == 0 ? START_CLEAR_M : 0.0;
            if (large) {
                next = farthestInSight(g, xs, ys, at, clearM);
            } else {
                while (next + 1 < n && g.visible(xs[at], ys[at], xs[next + 1], ys[next + 1], clearM)) {
                    next++;
                }
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

    /**
     * On a large area, a far chain point in sight of point {@code at}: the steps ahead double while
     * the point that far is in sight, then halve back to the last in sight (a chain of a thousand
     * cells checked one by one was a third of a floor's plan, JFR). Each leg is still checked; it
     * may end short of the farthest point in sight where the sight is broken and then clear again.
     */
    private static int farthestInSight(Grid g, double[] xs, double[] ys, int at, double clearM) {
        int n = xs.length;
        int good = at + 1;
        int step = 1;
        int bad = -1;
        while (good + step < n) {
            if (g.visible(xs[at], ys[at], xs[good + step], ys[good + step], clearM)) {
                good += step;
                step *= 2;
            } else {
                bad = good + step;
                break;
            }
        }
        if (bad < 0) {
            bad = n;
        }
        while (bad - good > 1) {
            int mid = (good + bad) >>> 1;
            if (g.visible(xs[at], ys[at], xs[mid], ys[mid], clearM)) {
                good = mid;
            } else {
                bad = mid;
            }
        }
        return good;
    }

    /** @return a heuristic's value times a weight (1: unchanged) */
    private static int weighted(int h, double weight) {
        return weight == 1.0 ? h : (int) (h * weight);
    }

    private static int heuristic(int i, int j, int gi, int gj, int reachTenths) {
        int dx = Math.abs(i - gi);
        int dy = Math.abs(j - gj);
        int octile = 10 * Math.max(dx, dy) + 4 * Math.min(dx, dy);
        return Math.max(0, octile - reachTenths);
    }

    /** Moves the entry at k up to its place, its cell with it. */
    private static void siftUp(long[] heap, int[] cells, int k) {
        long v = heap[k];
        int c = cells[k];
        while (k > 0) {
            int p = (k - 1) >>> 1;
            if (heap[p] <= v) {
                break;
            }
            heap[k] = heap[p];
            cells[k] = cells[p];
            k = p;
        }
        heap[k] = v;
        cells[k] = c;
    }

    /** Moves the entry at the top down to its place, its cell with it. */
    private static void siftDown(long[] heap, int[] cells, int size) {
        if (size == 0) {
            return;
        }
        long v = heap[0];
        int c = cells[0];
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
            cells[k] = cells[s];
            k = s;
        }
        heap[k] = v;
        cells[k] = c;
    }
}
