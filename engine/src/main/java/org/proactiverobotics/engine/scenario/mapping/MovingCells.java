package org.proactiverobotics.engine.scenario.mapping;

import java.util.Arrays;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * In a world shared with other robots, the cells that became occupied after the rays had seen them
 * free: something moved in (another robot, most likely; a wall is hit before any ray crosses it).
 * While such a cell is in the rays' view, the rays decide (they clear it when they see through
 * it); out of view, it loses one unit of evidence every {@value #DECAY_EVERY} scans, so that a
 * robot seen in a corridor the robot has since left is not a wall there for good (a route round
 * it through space never seen, and then no route at all, was what followed). A cell that faded
 * so once and is hit again after the rays saw it free is a wall, not a robot come back to the very
 * same cell: it is not followed again. A ray grazing along a wall crosses the cells its surface
 * lies on and takes them free, the next ray that hits them makes them "moved in", and a wall that
 * faded each time it was out of view had the robot plan through it, find it, and plan through it
 * again until the time limit (rooms worlds of four robots). Unless its body is a robot's: a faded
 * cell hit again is followed again when the cells joined to it fit in a square of a robot's width
 * ({@link #smallBody}); a wall's face joins the rest of the wall and stays. Another robot that
 * stood again where it had stood before, at a checkpoint or in a door, was otherwise a wall for
 * good there: the 8 checkpoints found unreachable in the generated worlds of four robots (seed 17)
 * were each walled in by such blobs only. Nor does a followed cell fade out of view when the cells
 * joined to it touch a cell that was hit before any ray crossed it: it is a wall's face that a
 * grazing ray took free, drawn again as the robot drove along it, and it is remembered as a faded
 * cell is (a wall that faded behind a robot had it turn back to the very same closed corridor end
 * three times in the generated corridors worlds of four robots; judged by size instead, robots
 * side by side round a station were walls too). At most {@value #CAPACITY} cells are followed
 * (the oldest are dropped) and {@value #FADED_CAPACITY} faded cells remembered (the first ones).
 * Kept in plain fields: saved with the rule that holds it.
 */
final class MovingCells {

    /** Out of view, a cell loses one unit of evidence every this many scans (evidence 6: gone in 1.5 s at 32 ms). */
    static final int DECAY_EVERY = 8;
    /** Occupied cells this many cells round a moved-in one are taken as the same body (0.1 m). */
    static final int NEIGHBOURS = 2;
    /** The most cells followed. */
    static final int CAPACITY = 1024;
    /**
     * The most faded cells remembered (the first ones): past the first 1 024, walls faded again and
     * again and robots shuttled under walls their maps had lost (27 of the 44 robots that failed in
     * the generated rooms and corridors worlds of four robots). 65 536 cells of 5 cm are 164 m² of
     * wall faces, more than any of those worlds holds; a slot is 8 bytes.
     */
    static final int FADED_CAPACITY = 1 << 16;
    /** A cell within this angle beyond the outermost rays still counts as in view, radians. */
    static final double VIEW_MARGIN_RAD = Math.toRadians(10);

    /**
     * A faded cell's body fits a robot when it spans at most a robot's width plus this many cells
     * (its side seen by the rays drawn on the grid, and where it stood the time before, a few
     * centimetres off: up to 7 cells for a robot of 0.12 m).
     */
    static final int BODY_EXTRA_CELLS = 2;

    private long[] cells = new long[64];
    private int count;
    private int scans;
    /** The cells that faded out of view once, sorted: hit again from free, they are walls. */
    private long[] faded = new long[0];
    /** The followed cells sorted, each one's {@link #joinedToWall} verdict and its search's queue: for one decay (not saved). */
    private transient long[] sorted;
    private transient byte[] verdict;
    private transient int[] bodyQueue;
    private static final byte UNJUDGED = 0;
    private static final byte SEARCHING = 1;
    private static final byte WALL = 2;
    private static final byte NOT_WALL = 3;
    /** {@link #smallBody}'s queue of joined cells, kept between calls (not saved). */
    private transient int[] queueI;
    private transient int[] queueJ;

    /**
     * Follows a cell that a ray hit after the rays had seen it free, and the occupied cells within
     * {@value #NEIGHBOURS} cells of it: the same body's side, first hit at the edge of the range
     * where nothing had been seen yet (left behind, it stood in a corridor for good).
     */
    void addWithNeighbours(OccupancyMap map, int i, int j, double robotRadiusM) {
        int span = (int) Math.ceil(2 * robotRadiusM / OccupancyMap.CELL_M) + BODY_EXTRA_CELLS;
        add(map, i, j, span);
        for (int b = -NEIGHBOURS; b <= NEIGHBOURS; b++) {
            for (int a = -NEIGHBOURS; a <= NEIGHBOURS; a++) {
                if ((a != 0 || b != 0) && map.get(i + a, j + b) == OccupancyMap.OCCUPIED) {
                    add(map, i + a, j + b, span);
                }
            }
        }
    }

    /** Follows a cell that a ray hit after the rays had seen it free, unless it faded once already (a wall). */
    void add(int i, int j) {
        add(null, i, j, 0);
    }

    /**
     * Follows a cell that a ray hit after the rays had seen it free, unless it faded once already and
     * its body on the map (null: none) is larger than a robot ({@code span} cells across).
     */
    private void add(OccupancyMap map, int i, int j, int span) {
        long key = key(i, j);
        if (Arrays.binarySearch(faded, key) >= 0 && (map == null || !smallBody(map, i, j, span))) {
            return;
        }
        for (int k = 0; k < count; k++) {
            if (cells[k] == key) {
                return;
            }
        }
        if (count == CAPACITY) {
            System.arraycopy(cells, 1, cells, 0, count - 1); // the oldest goes
            count--;
        } else if (count == cells.length) {
            cells = Arrays.copyOf(cells, Math.min(CAPACITY, 2 * cells.length));
        }
        cells[count++] = key;
    }

    /**
     * After a scan: every {@value #DECAY_EVERY} scans, the followed cells out of the rays' view
     * lose one unit of evidence; cells with none left are no longer followed, nor are cells whose
     * body touches a wall's cell (they stay, remembered as a faded cell is: {@link #joinedToWall}).
     *
     * @param map     the map
     * @param xM      the robot's x at the scan, metres
     * @param yM      its y, metres
     * @param yawRad  its heading, radians
     * @param radiusM its radius, metres
     * @param scan    the scan
     */
    void decay(OccupancyMap map, double xM, double yM, double yawRad, double radiusM, DistanceScan scan) {
        if (++scans % DECAY_EVERY != 0 || count == 0) {
            return;
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double a : scan.anglesRad()) {
            lo = Math.min(lo, a);
            hi = Math.max(hi, a);
        }
        // in view: where a ray that hits something beyond could still clear the cell
        double reach = radiusM + scan.rangeM() - UpdateMap.CLEAR_BEFORE_END_M;
        sortFollowed();
        int kept = 0;
        for (int k = 0; k < count; k++) {
            int i = (int) (cells[k] >> 32);
            int j = (int) cells[k];
            double dx = OccupancyMap.centre(i) - xM;
            double dy = OccupancyMap.centre(j) - yM;
            double bearing = Math.atan2(dy, dx) - yawRad;
            bearing = Math.atan2(Math.sin(bearing), Math.cos(bearing));
            boolean inView = Math.hypot(dx, dy) <= reach && bearing >= lo - VIEW_MARGIN_RAD && bearing <= hi + VIEW_MARGIN_RAD;
            if (!inView && map.evidence(i, j) > 0 && joinedToWall(map, cells[k])) {
                remember(cells[k]); // a wall's face that a grazing ray took free: kept, as a faded cell hit again is
                continue;
            }
            if (!inView && map.evidence(i, j) > 0) {
                map.clear(i, j);
                if (map.evidence(i, j) == 0) {
                    remember(cells[k]);
                }
            }
            if (map.evidence(i, j) > 0) {
                cells[kept++] = cells[k];
            }
        }
        count = kept;
    }

    /** Copies the followed cells, sorted, for {@link #joinedToWall}; no verdict yet. */
    private void sortFollowed() {
        if (sorted == null || sorted.length < count) {
            sorted = new long[cells.length];
            verdict = new byte[cells.length];
            bodyQueue = new int[cells.length];
        }
        System.arraycopy(cells, 0, sorted, 0, count);
        Arrays.sort(sorted, 0, count);
        Arrays.fill(verdict, 0, count, UNJUDGED);
    }

    /**
     * Whether a followed cell's body, the followed cells joined to it through gaps of up to
     * {@value #NEIGHBOURS} cells, touches an occupied cell that is not followed: a wall's cell, hit
     * before any ray crossed it (or a faded cell hit again). Its face was taken free by a grazing
     * ray and hit again as the robot drove along. Robots, even several side by side, are followed
     * whole and fade. One search a body, its verdict kept for its cells till the next decay.
     */
    private boolean joinedToWall(OccupancyMap map, long key) {
        int at = Arrays.binarySearch(sorted, 0, count, key);
        if (verdict[at] != UNJUDGED) {
            return verdict[at] == WALL;
        }
        int n = 0;
        bodyQueue[n++] = at;
        verdict[at] = SEARCHING;
        boolean wall = false;
        for (int h = 0; h < n && !wall; h++) {
            int ci = (int) (sorted[bodyQueue[h]] >> 32);
            int cj = (int) sorted[bodyQueue[h]];
            for (int b = -NEIGHBOURS; b <= NEIGHBOURS && !wall; b++) {
                for (int a = -NEIGHBOURS; a <= NEIGHBOURS; a++) {
                    if (map.get(ci + a, cj + b) != OccupancyMap.OCCUPIED) {
                        continue;
                    }
                    int other = Arrays.binarySearch(sorted, 0, count, key(ci + a, cj + b));
                    if (other < 0) {
                        wall = true;
                        break;
                    }
                    if (verdict[other] == UNJUDGED) {
                        verdict[other] = SEARCHING;
                        bodyQueue[n++] = other;
                    }
                }
            }
        }
        for (int q = 0; q < n; q++) {
            verdict[bodyQueue[q]] = wall ? WALL : NOT_WALL; // the cells queued so far are the same body
        }
        return wall;
    }

    /**
     * Lets go of every cell followed, and of every cell that faded once and is occupied again: the
     * robot found no way left on its map, and a blob another robot left joined to a wall's end (not
     * followed again, see {@link #smallBody}) may be all that walls it in. Taken free, the planner
     * leads the robot to look, and its rays draw again what is still there.
     *
     * @param map the map
     * @return how many occupied cells were taken free
     */
    int forget(OccupancyMap map) {
        int freed = 0;
        for (int k = 0; k < count; k++) {
            freed += free(map, cells[k]);
        }
        count = 0;
        for (long key : faded) {
            freed += free(map, key);
        }
        return freed;
    }

    private static int free(OccupancyMap map, long key) {
        int i = (int) (key >> 32);
        int j = (int) key;
        if (map.get(i, j) != OccupancyMap.OCCUPIED) {
            return 0;
        }
        map.set(i, j, OccupancyMap.FREE);
        return 1;
    }

    /**
     * Whether a cell and the cells joined to it fit in a square of {@code span} cells: a robot's side,
     * not a wall's. Occupied cells join through gaps of up to {@value #NEIGHBOURS} cells, cells that
     * faded once when they touch: a ray grazing a wall's face clears a cell, its hit then has the
     * cells {@value #NEIGHBOURS} round it followed and faded with it, and the first of them hit again
     * would otherwise stand alone, {@value #NEIGHBOURS} cells short of the rest of the wall (but
     * faded cells joined through gaps too bound a robot that stood by a faded wall to the wall).
     *
     * @param map  the map
     * @param i    the cell's column
     * @param j    its row
     * @param span the most cells the body may span along x and along y
     * @return true when the body fits
     */
    boolean smallBody(OccupancyMap map, int i, int j, int span) {
        int limit = (span + 2 * NEIGHBOURS) * (span + 2 * NEIGHBOURS);
        if (queueI == null || queueI.length < limit) {
            queueI = new int[limit];
            queueJ = new int[limit];
        }
        int[] qi = queueI;
        int[] qj = queueJ;
        int n = 1;
        qi[0] = i;
        qj[0] = j;
        int minI = i;
        int maxI = i;
        int minJ = j;
        int maxJ = j;
        for (int h = 0; h < n; h++) {
            for (int b = -NEIGHBOURS; b <= NEIGHBOURS; b++) {
                for (int a = -NEIGHBOURS; a <= NEIGHBOURS; a++) {
                    int ci = qi[h] + a;
                    int cj = qj[h] + b;
                    boolean next = Math.abs(a) <= 1 && Math.abs(b) <= 1;
                    if (map.get(ci, cj) != OccupancyMap.OCCUPIED && !(next && fadedOnce(ci, cj)) || queued(qi, qj, n, ci, cj)) {
                        continue;
                    }
                    minI = Math.min(minI, ci);
                    maxI = Math.max(maxI, ci);
                    minJ = Math.min(minJ, cj);
                    maxJ = Math.max(maxJ, cj);
                    if (maxI - minI >= span || maxJ - minJ >= span || n == limit) {
                        return false; // wider than a robot: a wall
                    }
                    qi[n] = ci;
                    qj[n++] = cj;
                }
            }
        }
        return true;
    }

    private boolean fadedOnce(int i, int j) {
        return Arrays.binarySearch(faded, key(i, j)) >= 0;
    }

    /** @return a cell's key: its column in the high half, its row in the low */
    private static long key(int i, int j) {
        return ((long) i << 32) | (j & 0xffffffffL);
    }

    private static boolean queued(int[] qi, int[] qj, int n, int i, int j) {
        for (int k = 0; k < n; k++) {
            if (qi[k] == i && qj[k] == j) {
                return true;
            }
        }
        return false;
    }

    /** Remembers a cell that faded out of view (up to {@value #FADED_CAPACITY}), kept sorted for the look-up. */
    private void remember(long key) {
        int at = Arrays.binarySearch(faded, key);
        if (at >= 0 || faded.length == FADED_CAPACITY) {
            return;
        }
        int insert = -at - 1;
        long[] grown = new long[faded.length + 1];
        System.arraycopy(faded, 0, grown, 0, insert);
        grown[insert] = key;
        System.arraycopy(faded, insert, grown, insert + 1, faded.length - insert);
        faded = grown;
    }
}
