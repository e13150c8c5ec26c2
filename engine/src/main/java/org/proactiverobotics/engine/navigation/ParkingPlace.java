package org.proactiverobotics.engine.navigation;

import java.util.ArrayDeque;
import java.util.Arrays;

import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * Where a robot that is done may stand in a shared world without closing a way: the place nearest
 * (along free cells of its own map) to where it wants to be that is not a <em>cut point</em> of the
 * free space. A place is a cut point when, with a body standing on it, the cells round it from
 * which another robot could pass fall apart into more than one piece within {@value #WINDOW_M} m:
 * a gap's mouth, a doorway, the narrow end of a corridor. In an open room or against a corridor's
 * wall they stay one piece (one can go round). Only the map decides, and only its seen cells: a
 * way is made of free cells seen by the rays, kept from occupied and from unknown cells alike by a
 * body and a margin (a wall's face fades from the map and the arena's rim is hardly ever hit: the
 * edge of the free cells is where the wall is).
 *
 * <p>All distances in metres; cells are the map's ({@link OccupancyMap#CELL_M}). Pure and
 * deterministic: the same map and point give the same place.
 */
public final class ParkingPlace {

    /** How far round the cut-point test looks, metres. */
    static final double WINDOW_M = 1.2;
    /** How far (along free cells) from the wanted point a place is looked for, metres. */
    static final double SEARCH_M = 2.0;
    /** What another robot's centre keeps from an occupied cell to pass, beyond the body's radius, metres. */
    static final double PASS_MARGIN_M = 0.06;
    /** What the parked body keeps from an occupied cell, beyond its radius, metres. */
    static final double PARK_MARGIN_M = 0.08;
    /** What another robot's centre keeps from the parked one's, beyond the two radii, metres. */
    static final double BODY_GAP_M = 0.4;

    /** The four neighbours' steps, x and y: a ring of equal steps, no diagonal leak. */
    private static final int[] STEP_A = {1, -1, 0, 0};
    private static final int[] STEP_B = {0, 0, 1, -1};

    private ParkingPlace() {
    }

    /**
     * @param map     the robot's map
     * @param xM      where it wants to stand, x
     * @param yM      its y
     * @param radiusM the body's radius (the others' taken as the same)
     * @return {x, y} of the nearest place that closes no way, or the wanted point when none is within {@value #SEARCH_M} m
     */
    public static double[] near(OccupancyMap map, double xM, double yM, double radiusM) {
        int ci = OccupancyMap.cell(xM);
        int cj = OccupancyMap.cell(yM);
        int h = (int) Math.ceil((SEARCH_M + WINDOW_M) / OccupancyMap.CELL_M) + 2;
        int n = 2 * h + 1;
        // cell (ci - h + a, cj - h + b) is index b * n + a
        boolean[] known = new boolean[n * n];
        for (int b = 0; b < n; b++) {
            for (int a = 0; a < n; a++) {
                known[b * n + a] = map.get(ci - h + a, cj - h + b) == OccupancyMap.FREE;
            }
        }
        // distance (in cells, squared) of each cell from the nearest occupied one, up to the park keep
        double parkKeep = (radiusM + PARK_MARGIN_M) / OccupancyMap.CELL_M;
        double passKeep = (radiusM + PASS_MARGIN_M) / OccupancyMap.CELL_M;
        boolean[] passable = new boolean[n * n];
        boolean[] roomy = new boolean[n * n];
        Arrays.fill(passable, true);
        Arrays.fill(roomy, true);
        // a wall's face fades from the map and the arena's rim is hardly ever hit: the free cells' edge is the wall
        double unknownBodyKeep = radiusM / OccupancyMap.CELL_M;
        int reach = (int) Math.ceil(parkKeep);
        for (int c = 0; c < n * n; c++) {
            if (known[c]) {
                continue;
            }
            int oa = c % n;
            int ob = c / n;
            boolean occupied = map.get(ci - h + oa, cj - h + ob) == OccupancyMap.OCCUPIED;
            double roomyKeep = occupied ? parkKeep : unknownBodyKeep;
            for (int db = -reach; db <= reach; db++) {
                for (int da = -reach; da <= reach; da++) {
                    int a = oa + da;
                    int b = ob + db;
                    if (a < 0 || b < 0 || a >= n || b >= n) {
                        continue;
                    }
                    double d2 = da * da + db * db;
                    if (d2 <= roomyKeep * roomyKeep) {
                        roomy[b * n + a] = false;
                    }
                    if (d2 <= passKeep * passKeep) {
                        passable[b * n + a] = false;
                    }
                }
            }
        }
        // the candidates in order of their distance along passable cells from the wanted point
        int searchCells = (int) Math.round(SEARCH_M / OccupancyMap.CELL_M);
        int[] dist = new int[n * n];
        Arrays.fill(dist, -1);
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        int start = h * n + h;
        dist[start] = 0;
        queue.add(start);
        Cuts cuts = new Cuts(n, passable, known, radiusM);
        while (!queue.isEmpty()) {
            int c = queue.poll();
            int a = c % n;
            int b = c / n;
            if (roomy[c] && known[c] && !cuts.cut(a, b)) {
                return new double[] {OccupancyMap.centre(ci - h + a), OccupancyMap.centre(cj - h + b)};
            }
            if (dist[c] >= searchCells) {
                continue;
            }
            for (int d = 0; d < 4; d++) {
                int na = a + STEP_A[d];
                int nb = b + STEP_B[d];
                int nc = nb * n + na;
                if (dist[nc] < 0 && passable[nc]) {
                    dist[nc] = dist[c] + 1;
                    queue.add(nc);
                }
            }
        }
        return new double[] {xM, yM};
    }

    /** The cut-point test on the window's grid, with its scratch arrays. */
    private static final class Cuts {
        private final int n;
        private final boolean[] passable;
        private final boolean[] known;
        private final double blockCells;
        private final double ringCells;
        private final double windowCells;
        private final int[] mark;
        /** Cells reached from the place itself within the ring, this stamp: the other side of a thin wall is not. */
        private final int[] near;
        private int stamp;
        private final int[] stack;

        Cuts(int n, boolean[] passable, boolean[] known, double radiusM) {
            this.n = n;
            this.passable = passable;
            this.known = known;
            this.blockCells = (2 * radiusM + BODY_GAP_M) / OccupancyMap.CELL_M;
            this.ringCells = blockCells + 2;
            this.windowCells = WINDOW_M / OccupancyMap.CELL_M;
            this.mark = new int[n * n];
            this.near = new int[n * n];
            this.stack = new int[n * n];
        }

        private boolean inWindow(int a, int b, int pa, int pb) {
            if (a < 0 || b < 0 || a >= n || b >= n || !passable[b * n + a]) {
                return false;
            }
            double d2 = (a - pa) * (a - pa) + (b - pb) * (b - pb);
            return d2 > blockCells * blockCells && d2 <= windowCells * windowCells;
        }

        /** @return whether a body on cell (pa, pb) splits the passable cells round it into pieces that each hold a seen ring cell */
        boolean cut(int pa, int pb) {
            stamp++;
            reachNear(pa, pb);
            int pieces = 0;
            int r = (int) Math.ceil(ringCells);
            for (int b = pb - r; b <= pb + r; b++) {
                for (int a = pa - r; a <= pa + r; a++) {
                    if (!inWindow(a, b, pa, pb) || mark[b * n + a] == stamp || near[b * n + a] != stamp) {
                        continue;
                    }
                    double d2 = (a - pa) * (a - pa) + (b - pb) * (b - pb);
                    if (d2 > ringCells * ringCells) {
                        continue;
                    }
                    if (fill(a, b, pa, pb) && ++pieces > 1) {
                        return true;
                    }
                }
            }
            return false;
        }

        /** Marks the passable cells within the ring's outer radius reached from the place, without blocking it. */
        private void reachNear(int pa, int pb) {
            int top = 0;
            stack[top++] = pb * n + pa;
            near[pb * n + pa] = stamp;
            while (top > 0) {
                int c = stack[--top];
                int a = c % n;
                int b = c / n;
                for (int d = 0; d < 4; d++) {
                    int na = a + STEP_A[d];
                    int nb = b + STEP_B[d];
                    int nc = nb * n + na;
                    if (na >= 0 && nb >= 0 && na < n && nb < n && passable[nc] && near[nc] != stamp
                            && (na - pa) * (na - pa) + (nb - pb) * (nb - pb) <= ringCells * ringCells) {
                        near[nc] = stamp;
                        stack[top++] = nc;
                    }
                }
            }
        }

        /** Marks the piece holding (a, b); @return whether it holds a seen-free ring cell. */
        private boolean fill(int a0, int b0, int pa, int pb) {
            boolean seen = false;
            int top = 0;
            stack[top++] = b0 * n + a0;
            mark[b0 * n + a0] = stamp;
            while (top > 0) {
                int c = stack[--top];
                int a = c % n;
                int b = c / n;
                double d2 = (a - pa) * (a - pa) + (b - pb) * (b - pb);
                if (known[c] && near[c] == stamp && d2 <= ringCells * ringCells) {
                    seen = true;
                }
                for (int d = 0; d < 4; d++) {
                    int na = a + STEP_A[d];
                    int nb = b + STEP_B[d];
                    if (inWindow(na, nb, pa, pb) && mark[nb * n + na] != stamp) {
                        mark[nb * n + na] = stamp;
                        stack[top++] = nb * n + na;
                    }
                }
            }
            return seen;
        }
    }
}
