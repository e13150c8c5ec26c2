package org.proactiverobotics.app.generate;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Shortest paths for the robot's centre on an occupancy grid of a world: a cell is free when the
 * robot (its radius plus a clearance) fits there, inside the arena (a circle or a rectangle) and off
 * every obstacle; A* over the 8 neighbours. What {@code generate} and {@code import-map} use to check a
 * world solvable before writing it. Remembers the lengths it found.
 */
public final class GridPlanner {

    /** Grid resolution, metres. */
    public static final double CELL_M = 0.05;
    private static final double SQRT2 = Math.sqrt(2);

    private final double originX;
    private final double originY;
    /** Cells along x. */
    private final int size;
    /** Cells along y (as many as along x in a circular arena). */
    private final int rows;
    private final boolean[] free;
    /** Lengths already found, by start and goal cell: a tour's legs are asked for more than once. */
    private final Map<Long, Double> found = new ConcurrentHashMap<>();

    /**
     * @param world      the world
     * @param clearanceM room kept between the robot's rim and anything, metres
     */
    public GridPlanner(WorldSpec world, double clearanceM) {
        WorldSpec.Arena arena = world.arena();
        double body = world.robot().radiusM() + clearanceM;
        if (arena.isCircle()) {
            double r = arena.radiusM();
            this.originX = -r;
            this.originY = -r;
            this.size = (int) Math.ceil(2 * r / CELL_M) + 1;
            this.rows = size;
        } else {
            this.originX = arena.minX();
            this.originY = arena.minY();
            this.size = (int) Math.ceil(arena.widthM() / CELL_M) + 1;
            this.rows = (int) Math.ceil(arena.heightM() / CELL_M) + 1;
        }
        this.free = new boolean[size * rows];
        if (arena.isCircle()) {
            for (int j = 0; j < rows; j++) {
                for (int i = 0; i < size; i++) {
                    free[j * size + i] = Math.hypot(originX + i * CELL_M, originY + j * CELL_M) <= arena.radiusM() - body;
                }
            }
        } else {
            // a rectangle's inside() is its nearest side's distance: far enough from both x sides and both y sides,
            // the same sums as inside() makes, by column and by row instead of for each of millions of cells
            boolean[] column = new boolean[size];
            for (int i = 0; i < size; i++) {
                double x = originX + i * CELL_M;
                column[i] = x - arena.minX() >= body && arena.maxX() - x >= body;
            }
            for (int j = 0; j < rows; j++) {
                double y = originY + j * CELL_M;
                if (y - arena.minY() >= body && arena.maxY() - y >= body) {
                    System.arraycopy(column, 0, free, j * size, size);
                }
            }
        }
        // each obstacle closes only the cells near it: a floor of thousands of boxes costs their area, not cells x boxes
        for (WorldSpec.Obstacle o : world.obstacles()) {
            // half the obstacle's bounding box along x and y (a box turned by its angle), plus the body
            double cos = Math.abs(Math.cos(o.angleRad()));
            double sin = Math.abs(Math.sin(o.angleRad()));
            double reachX = (o.isCircle() ? o.radiusM() : (cos * o.widthM() + sin * o.heightM()) / 2) + body;
            double reachY = (o.isCircle() ? o.radiusM() : (sin * o.widthM() + cos * o.heightM()) / 2) + body;
            int i0 = Math.max(0, (int) Math.floor((o.x() - reachX - originX) / CELL_M) - 1);
            int i1 = Math.min(size - 1, (int) Math.ceil((o.x() + reachX - originX) / CELL_M) + 1);
            int j0 = Math.max(0, (int) Math.floor((o.y() - reachY - originY) / CELL_M) - 1);
            int j1 = Math.min(rows - 1, (int) Math.ceil((o.y() + reachY - originY) / CELL_M) + 1);
            for (int j = j0; j <= j1; j++) {
                for (int i = i0; i <= i1; i++) {
                    int c = j * size + i;
                    if (free[c] && o.distanceTo(originX + i * CELL_M, originY + j * CELL_M) <= body) {
                        free[c] = false;
                    }
                }
            }
        }
    }

    /** @return cells along x */
    public int columns() {
        return size;
    }

    /** @return cells along y */
    public int rows() {
        return rows;
    }

    /** @return x of column i's cell centre, metres */
    public double x(int i) {
        return originX + i * CELL_M;
    }

    /** @return y of row j's cell centre, metres */
    public double y(int j) {
        return originY + j * CELL_M;
    }

    /** @return a copy of every cell's {@link #free} flag, row by row (cell (i, j) at j * columns() + i) */
    public boolean[] freeCells() {
        return free.clone();
    }

    /** @return whether the robot's centre may be at cell (i, j) with its clearance; cells off the grid are not */
    public boolean free(int i, int j) {
        return i >= 0 && j >= 0 && i < size && j < rows && free[j * size + i];
    }

    /**
     * @return the length of a shortest free path between two points, metres, or
     *         {@link Double#POSITIVE_INFINITY} when there is none (either end blocked included); the same
     *         both ways, to the last bit
     */
    public double distance(double fromX, double fromY, double toX, double toY) {
        int start = cell(fromX, fromY);
        int goal = cell(toX, toY);
        if (start < 0 || goal < 0 || !free[start] || !free[goal]) {
            return Double.POSITIVE_INFINITY;
        }
        Double known = found.get(key(start, goal));
        if (known == null) {
            searchAndKeep(start, goal);
            known = found.get(key(start, goal));
        }
        return known;
    }

    /**
     * Finds the lengths between these pairs of points on every core, for {@link #distance} to answer at once
     * afterwards, each pair once (a length is the same both ways): each search reads only the grid, so the
     * answers are those one core would find.
     *
     * @param pairs each {fromX, fromY, toX, toY}, metres
     */
    public void prefetch(List<double[]> pairs) {
        Map<Long, int[]> asked = new LinkedHashMap<>();
        for (double[] p : pairs) {
            int start = cell(p[0], p[1]);
            int goal = cell(p[2], p[3]);
            if (start >= 0 && goal >= 0 && free[start] && free[goal] && !found.containsKey(key(start, goal))
                    && !asked.containsKey(key(goal, start))) {
                asked.put(key(start, goal), new int[] {start, goal});
            }
        }
        asked.values().parallelStream().forEach(p -> searchAndKeep(p[0], p[1]));
    }

    /**
     * The cells a robot starting at (x, y) can reach: free cells joined by free cells side by side (a
     * diagonal step needs both cells beside it free, so these are the cells {@link #distance} finds a path to).
     *
     * @return one flag per cell, row by row; none set when (x, y) is blocked or off the grid
     */
    public boolean[] reachableFrom(double x, double y) {
        boolean[] reached = new boolean[free.length];
        int start = cell(x, y);
        if (start < 0 || !free[start]) {
            return reached;
        }
        int[] queue = new int[free.length];
        int head = 0;
        int tail = 0;
        queue[tail++] = start;
        reached[start] = true;
        while (head < tail) {
            int c = queue[head++];
            int cx = c % size;
            int cy = c / size;
            int[] next = {cx > 0 ? c - 1 : -1, cx < size - 1 ? c + 1 : -1, cy > 0 ? c - size : -1, cy < rows - 1 ? c + size : -1};
            for (int n : next) {
                if (n >= 0 && free[n] && !reached[n]) {
                    reached[n] = true;
                    queue[tail++] = n;
                }
            }
        }
        return reached;
    }

    /** @return whether (x, y)'s cell is among the cells flagged (by {@link #reachableFrom}) */
    public boolean within(boolean[] cells, double x, double y) {
        int c = cell(x, y);
        return c >= 0 && cells[c];
    }

    /**
     * A search's arrays, kept by each thread from search to search: a cell's steps count only where its
     * mark is this search's, so that a search on a floor of millions of cells does not first allocate and
     * fill arrays of its whole area.
     */
    private static final class Scratch {
        private static final ThreadLocal<Scratch> OF_THREAD = ThreadLocal.withInitial(Scratch::new);
        /** Straight and diagonal steps of the shortest way found so far to each cell reached. */
        int[] straight = new int[0];
        int[] diagonal = new int[0];
        int[] reached = new int[0];
        /** Marked when a cell's neighbours were looked at with its steps as they are now. */
        int[] expanded = new int[0];
        int stamp;
        final CellBuckets open = new CellBuckets();

        /** @return this thread's arrays for n cells, with a fresh stamp and an empty open list */
        static Scratch forCells(int n) {
            Scratch s = OF_THREAD.get();
            if (s.reached.length < n || s.stamp == Integer.MAX_VALUE) {
                int length = Math.max(n, s.reached.length);
                s.straight = new int[length];
                s.diagonal = new int[length];
                s.reached = new int[length];
                s.expanded = new int[length];
                s.stamp = 0;
            }
            s.stamp++;
            s.open.clear();
            return s;
        }
    }

    /** Searches from one cell to another and keeps the length, both ways, in {@link #found}. */
    private void searchAndKeep(int start, int goal) {
        double metres = search(start, goal);
        found.put(key(start, goal), metres);
        found.put(key(goal, start), metres);
    }

    /**
     * A* from cell to cell with the octile distance as its estimate (the exact length where nothing is in
     * the way, so the search keeps close to the shortest way). The open cells wait in buckets of
     * {@link CellBuckets#WIDTH} cell by their estimate instead of a heap, the last in a bucket first; as
     * a bucket's cells are not in order within it, a cell may be looked at before its shortest way is
     * known, and is then looked at again when that way is found; the goal's length is final once its
     * bucket is empty (every way still open is longer). A way's length is kept as its counts of straight
     * and diagonal steps: a + b√2 for whole a and b is the same number only for the same a and b, so the
     * shortest way's counts are unique and its length, computed from them, is the same whichever of the
     * shortest ways the search met, and the same from either end.
     *
     * @return the length in metres, or infinity
     */
    private double search(int start, int goal) {
        Scratch s = Scratch.forCells(size * rows);
        int[] straight = s.straight;
        int[] diagonal = s.diagonal;
        int[] reached = s.reached;
        int[] expanded = s.expanded;
        int stamp = s.stamp;
        straight[start] = 0;
        diagonal[start] = 0;
        reached[start] = stamp;
        int gx = goal % size;
        int gy = goal / size;
        CellBuckets open = s.open;
        open.add(CellBuckets.bucket(estimate(start, gx, gy)), start);
        boolean goalFound = false;
        for (int bucket = open.first(); open.waiting() > 0; bucket++) {
            while (open.any(bucket)) {
                int c = open.take(bucket);
                if (expanded[c] == stamp) {
                    continue; // looked at already with the steps it has now: this entry is an older, longer way's
                }
                expanded[c] = stamp;
                if (c == goal) {
                    goalFound = true;
                    continue;
                }
                int cx = c % size;
                int cy = c / size;
                int ca = straight[c];
                int cb = diagonal[c];
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dx = -1; dx <= 1; dx++) {
                        int nx = cx + dx;
                        int ny = cy + dy;
                        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= size || ny >= rows) {
                            continue;
                        }
                        int n = ny * size + nx;
                        boolean diag = dx != 0 && dy != 0;
                        // a diagonal step must not cut a blocked corner
                        if (!free[n] || (diag && (!free[cy * size + nx] || !free[ny * size + cx]))) {
                            continue;
                        }
                        int na = diag ? ca : ca + 1;
                        int nb = diag ? cb + 1 : cb;
                        double length = na + nb * SQRT2;
                        if (reached[n] != stamp || length < straight[n] + diagonal[n] * SQRT2) { // not reached: at infinity
                            straight[n] = na;
                            diagonal[n] = nb;
                            reached[n] = stamp;
                            expanded[n] = 0; // to be looked at (again) with this way
                            // never behind the bucket being emptied, whatever the last bit of the sum
                            open.add(Math.max(bucket, CellBuckets.bucket(length + estimate(n, gx, gy))), n);
                        }
                    }
                }
            }
            if (goalFound) {
                return (straight[goal] + diagonal[goal] * SQRT2) * CELL_M;
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /**
     * The open list: cells in buckets by their estimate, {@link #WIDTH} cell wide, used round (a step
     * raises the estimate by at most 2√2 cells, so the cells waiting lie within {@link #RING} buckets of
     * the one being emptied); in a bucket, the last added leaves first.
     */
    private static final class CellBuckets {
        /** A bucket's width, cells. */
        static final double WIDTH = 1.0 / 8;
        /** Buckets in use at once: a power of two above 2√2 / WIDTH + 1. */
        private static final int RING = 32;
        private final int[][] cells = new int[RING][16];
        private final int[] filled = new int[RING];
        private int waiting;
        private int lowest = Integer.MAX_VALUE;

        /** @return the bucket of an estimate, cells */
        static int bucket(double estimate) {
            return (int) (estimate / WIDTH);
        }

        void clear() {
            Arrays.fill(filled, 0);
            waiting = 0;
            lowest = Integer.MAX_VALUE;
        }

        /** @return the lowest bucket anything was added to since {@link #clear} */
        int first() {
            return lowest;
        }

        int waiting() {
            return waiting;
        }

        void add(int bucket, int cell) {
            int b = bucket & (RING - 1);
            if (filled[b] == cells[b].length) {
                cells[b] = Arrays.copyOf(cells[b], filled[b] * 2);
            }
            cells[b][filled[b]++] = cell;
            waiting++;
            lowest = Math.min(lowest, bucket);
        }

        boolean any(int bucket) {
            return filled[bucket & (RING - 1)] > 0;
        }

        int take(int bucket) {
            int b = bucket & (RING - 1);
            waiting--;
            return cells[b][--filled[b]];
        }
    }

    /** The octile distance in cells: diagonal steps along the shorter side, straight ones for the rest. */
    private double estimate(int c, int gx, int gy) {
        int dx = Math.abs(c % size - gx);
        int dy = Math.abs(c / size - gy);
        return Math.abs(dx - dy) + Math.min(dx, dy) * SQRT2;
    }

    private long key(int start, int goal) {
        return (long) start * free.length + goal;
    }

    private int cell(double x, double y) {
        int i = (int) Math.round((x - originX) / CELL_M);
        int j = (int) Math.round((y - originY) / CELL_M);
        return i < 0 || j < 0 || i >= size || j >= rows ? -1 : j * size + i;
    }
}
