package org.proactiverobotics.app.generate;

import java.util.Arrays;
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
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < size; i++) {
                double x = originX + i * CELL_M;
                double y = originY + j * CELL_M;
                free[j * size + i] = arena.isCircle() ? Math.hypot(x, y) <= arena.radiusM() - body : arena.inside(x, y) >= body;
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

    /** @return whether the robot's centre may be at cell (i, j) with its clearance; cells off the grid are not */
    public boolean free(int i, int j) {
        return i >= 0 && j >= 0 && i < size && j < rows && free[j * size + i];
    }

    /**
     * @return the length of a shortest free path between two points, metres, or
     *         {@link Double#POSITIVE_INFINITY} when there is none (either end blocked included)
     */
    public double distance(double fromX, double fromY, double toX, double toY) {
        int start = cell(fromX, fromY);
        int goal = cell(toX, toY);
        if (start < 0 || goal < 0 || !free[start] || !free[goal]) {
            return Double.POSITIVE_INFINITY;
        }
        Long key = (long) start * free.length + goal;
        Double known = found.get(key);
        if (known == null) {
            known = search(start, goal);
            found.put(key, known);
        }
        return known;
    }

    /**
     * Finds the lengths between these pairs of points on every core, for {@link #distance} to answer at once
     * afterwards: each search reads only the grid, so the answers are those one core would find.
     *
     * @param pairs each {fromX, fromY, toX, toY}, metres
     */
    public void prefetch(List<double[]> pairs) {
        pairs.parallelStream().forEach(p -> distance(p[0], p[1], p[2], p[3]));
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

    /** A* from cell to cell: the length in metres, or infinity. */
    private double search(int start, int goal) {
        double[] g = new double[size * rows];
        Arrays.fill(g, Double.POSITIVE_INFINITY);
        g[start] = 0;
        int gx = goal % size;
        int gy = goal / size;
        CellHeap open = new CellHeap();
        open.add(heuristic(start, gx, gy), start);
        boolean[] closed = new boolean[size * rows];
        while (!open.isEmpty()) {
            int c = open.poll();
            if (c == goal) {
                return g[c] * CELL_M;
            }
            if (closed[c]) {
                continue;
            }
            closed[c] = true;
            int cx = c % size;
            int cy = c / size;
            for (int dy = -1; dy <= 1; dy++) {
                for (int dx = -1; dx <= 1; dx++) {
                    int nx = cx + dx;
                    int ny = cy + dy;
                    if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= size || ny >= rows) {
                        continue;
                    }
                    int n = ny * size + nx;
                    // a diagonal step must not cut a blocked corner
                    if (!free[n] || closed[n] || (dx != 0 && dy != 0 && (!free[cy * size + nx] || !free[ny * size + cx]))) {
                        continue;
                    }
                    double step = g[c] + (dx != 0 && dy != 0 ? Math.sqrt(2) : 1);
                    if (step < g[n]) {
                        g[n] = step;
                        open.add(step + heuristic(n, gx, gy), n);
                    }
                }
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /**
     * The open list: cells by their estimate, lowest first. The binary heap of java.util.PriorityQueue step
     * for step (the same sift up and down), on arrays: equal estimates leave in the same order, so paths and
     * their lengths are those the planner always found, without an object a cell.
     */
    private static final class CellHeap {
        private double[] keys = new double[1024];
        private int[] cells = new int[1024];
        private int size;

        boolean isEmpty() {
            return size == 0;
        }

        void add(double key, int cell) {
            if (size == keys.length) {
                keys = Arrays.copyOf(keys, size * 2);
                cells = Arrays.copyOf(cells, size * 2);
            }
            int k = size++;
            while (k > 0) {
                int parent = (k - 1) >>> 1;
                if (Double.compare(key, keys[parent]) >= 0) {
                    break;
                }
                keys[k] = keys[parent];
                cells[k] = cells[parent];
                k = parent;
            }
            keys[k] = key;
            cells[k] = cell;
        }

        int poll() {
            int result = cells[0];
            int n = --size;
            double key = keys[n];
            int cell = cells[n];
            if (n > 0) {
                int k = 0;
                int half = n >>> 1;
                while (k < half) {
                    int child = (k << 1) + 1;
                    int right = child + 1;
                    if (right < n && Double.compare(keys[child], keys[right]) > 0) {
                        child = right;
                    }
                    if (Double.compare(key, keys[child]) <= 0) {
                        break;
                    }
                    keys[k] = keys[child];
                    cells[k] = cells[child];
                    k = child;
                }
                keys[k] = key;
                cells[k] = cell;
            }
            return result;
        }
    }

    /**
     * The straight-line distance in cells. sqrt(dx² + dy²) of whole numbers equals Math.hypot's result for
     * every pair up to 4 000 cells (checked one by one), so the searches are those hypot gave, at a fraction of its cost.
     */
    private double heuristic(int c, int gx, int gy) {
        double dx = c % size - gx;
        double dy = c / size - gy;
        return Math.sqrt(dx * dx + dy * dy);
    }

    private int cell(double x, double y) {
        int i = (int) Math.round((x - originX) / CELL_M);
        int j = (int) Math.round((y - originY) / CELL_M);
        return i < 0 || j < 0 || i >= size || j >= rows ? -1 : j * size + i;
    }
}
