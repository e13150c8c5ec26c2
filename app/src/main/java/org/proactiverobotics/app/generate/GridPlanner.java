package org.proactiverobotics.app.generate;

import java.util.Arrays;
import java.util.PriorityQueue;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Shortest paths for the robot's centre on an occupancy grid of a world: a cell is free when the
 * robot (its radius plus a clearance) fits there, inside the arena and off every obstacle; A* over
 * the 8 neighbours. What {@code generate} uses to check a world solvable before writing it.
 */
public final class GridPlanner {

    /** Grid resolution, metres. */
    public static final double CELL_M = 0.05;

    private final double originX;
    private final double originY;
    private final int size;
    private final boolean[] free;

    /**
     * @param world      the world
     * @param clearanceM room kept between the robot's rim and anything, metres
     */
    public GridPlanner(WorldSpec world, double clearanceM) {
        double r = world.arena().radiusM();
        this.originX = -r;
        this.originY = -r;
        this.size = (int) Math.ceil(2 * r / CELL_M) + 1;
        this.free = new boolean[size * size];
        double body = world.robot().radiusM() + clearanceM;
        for (int j = 0; j < size; j++) {
            for (int i = 0; i < size; i++) {
                double x = originX + i * CELL_M;
                double y = originY + j * CELL_M;
                boolean ok = Math.hypot(x, y) <= r - body;
                for (WorldSpec.Obstacle o : world.obstacles()) {
                    if (!ok) {
                        break;
                    }
                    ok = o.distanceTo(x, y) > body;
                }
                free[j * size + i] = ok;
            }
        }
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
        double[] g = new double[size * size];
        Arrays.fill(g, Double.POSITIVE_INFINITY);
        g[start] = 0;
        int gx = goal % size;
        int gy = goal / size;
        PriorityQueue<double[]> open = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        open.add(new double[] {heuristic(start, gx, gy), start});
        boolean[] closed = new boolean[size * size];
        while (!open.isEmpty()) {
            int c = (int) open.poll()[1];
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
                    if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= size || ny >= size) {
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
                        open.add(new double[] {step + heuristic(n, gx, gy), n});
                    }
                }
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    private double heuristic(int c, int gx, int gy) {
        return Math.hypot(c % size - gx, c / size - gy);
    }

    private int cell(double x, double y) {
        int i = (int) Math.round((x - originX) / CELL_M);
        int j = (int) Math.round((y - originY) / CELL_M);
        return i < 0 || j < 0 || i >= size || j >= size ? -1 : j * size + i;
    }
}
