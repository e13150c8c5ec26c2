package org.proactiverobotics.sim2d;

import java.util.ArrayList;
import java.util.List;
import java.util.function.ToDoubleFunction;

import org.dyn4j.collision.narrowphase.Raycast;
import org.dyn4j.collision.narrowphase.RaycastDetector;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.AABB;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Vector2;

/**
 * The static bodies' fixtures (arena wall, obstacles) in a uniform grid, for the distance sensors' rays.
 * <p>
 * dyn4j's {@code raycastClosest} walks its tree down every node whose AABB (each grown by 0.2 m) the whole
 * ray crosses and casts against every such fixture; on a floor of thousands of boxes that is most of a
 * sensor read. Here the ray walks the grid's cells in order from its start and stops once the nearest hit
 * found lies before the next cell, casting with the world's own ray-cast detector against each fixture met
 * whose box (grown by a millimetre) the ray crosses before that hit.
 * The nearest distance is the minimum over the fixtures cast against, whatever their order, so it is the
 * distance dyn4j finds, bit for bit. Cells are {@value #CELL_M} m (larger on a very large arena, so that the
 * grid stays under {@value #MAX_CELLS} cells). Read-only once built: any number of {@link Query} objects may
 * use it at once.
 */
final class StaticRayIndex {

    /** Side of a cell, metres: about a wall piece, and a sensor ray (about 1 m) crosses a handful. */
    static final double CELL_M = 0.25;
    /** Most cells in the grid. */
    static final int MAX_CELLS = 4_000_000;
    /**
     * Metres added round each fixture's box and to the stop distance: a computed hit may lie a little off the
     * exact boundary, and a cell the ray enters this much past the nearest hit cannot hold a nearer one.
     */
    private static final double MARGIN_M = 1e-3;

    private final RaycastDetector detector;
    private final double minX;
    private final double minY;
    private final double maxX;
    private final double maxY;
    private final double cell;
    private final int nx;
    private final int ny;
    /** Start of each cell's run in {@link #items} (CSR layout: cell c holds items[start[c] .. start[c+1]-1]). */
    private final int[] start;
    /** Indices into {@link #fixtures} and {@link #bodies}. */
    private final int[] items;
    private final BodyFixture[] fixtures;
    private final Body[] bodies;
    /** Each fixture's box grown by twice {@link #MARGIN_M}: min x, min y, max x, max y, side by side. */
    private final double[] boxes;

    /**
     * @param statics  the static bodies (their fixtures and transforms must not change afterwards)
     * @param detector the world's ray-cast detector (the same computation as the world's ray casts)
     */
    StaticRayIndex(List<Body> statics, RaycastDetector detector) {
        this.detector = detector;
        List<BodyFixture> fs = new ArrayList<>();
        List<Body> bs = new ArrayList<>();
        List<AABB> boxes = new ArrayList<>();
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (Body b : statics) {
            for (BodyFixture f : b.getFixtures()) {
                AABB box = f.getShape().createAABB(b.getTransform());
                box.expand(2 * MARGIN_M);
                fs.add(f);
                bs.add(b);
                boxes.add(box);
                x0 = Math.min(x0, box.getMinX());
                y0 = Math.min(y0, box.getMinY());
                x1 = Math.max(x1, box.getMaxX());
                y1 = Math.max(y1, box.getMaxY());
            }
        }
        this.fixtures = fs.toArray(new BodyFixture[0]);
        this.bodies = bs.toArray(new Body[0]);
        this.boxes = new double[4 * fixtures.length];
        for (int i = 0; i < fixtures.length; i++) {
            AABB box = boxes.get(i);
            this.boxes[4 * i] = box.getMinX();
            this.boxes[4 * i + 1] = box.getMinY();
            this.boxes[4 * i + 2] = box.getMaxX();
            this.boxes[4 * i + 3] = box.getMaxY();
        }
        if (fixtures.length == 0) {
            x0 = y0 = x1 = y1 = 0.0;
        }
        double c = CELL_M;
        while (cells(x1 - x0, c) * (long) cells(y1 - y0, c) > MAX_CELLS) {
            c *= 2.0;
        }
        this.minX = x0;
        this.minY = y0;
        this.maxX = x1;
        this.maxY = y1;
        this.cell = c;
        this.nx = cells(x1 - x0, c);
        this.ny = cells(y1 - y0, c);
        int[] count = new int[nx * ny + 1];
        for (AABB box : boxes) {
            forCells(box, (cx, cy) -> count[cy * nx + cx + 1]++);
        }
        for (int i = 1; i < count.length; i++) {
            count[i] += count[i - 1];
        }
        this.start = count.clone();
        this.items = new int[count[count.length - 1]];
        int[] next = count;
        for (int i = 0; i < boxes.size(); i++) {
            int item = i;
            forCells(boxes.get(i), (cx, cy) -> items[next[cy * nx + cx]++] = item);
        }
    }

    private static int cells(double extent, double cell) {
        return Math.max(1, (int) Math.ceil(extent / cell));
    }

    private interface CellAction {
        void at(int cx, int cy);
    }

    private void forCells(AABB box, CellAction action) {
        int cx0 = clamp((int) Math.floor((box.getMinX() - minX) / cell), nx);
        int cx1 = clamp((int) Math.floor((box.getMaxX() - minX) / cell), nx);
        int cy0 = clamp((int) Math.floor((box.getMinY() - minY) / cell), ny);
        int cy1 = clamp((int) Math.floor((box.getMaxY() - minY) / cell), ny);
        for (int cy = cy0; cy <= cy1; cy++) {
            for (int cx = cx0; cx <= cx1; cx++) {
                action.at(cx, cy);
            }
        }
    }

    private static int clamp(int i, int n) {
        return i < 0 ? 0 : Math.min(i, n - 1);
    }

    /**
     * The least of {@code distance} over the static fixtures whose cells meet the box from (x0, y0) to (x1, y1),
     * metres, or {@code bound} when none is less. Those fixtures include every one whose box meets the box (and
     * some more, some more than once), so a minimum over them is the minimum over what the world's own box query
     * finds, whenever whatever lies nearer than {@code bound} must meet the box.
     */
    double least(double x0, double y0, double x1, double y1, double bound, ToDoubleFunction<Object> distance) {
        int cx0 = clamp((int) Math.floor((x0 - minX) / cell), nx);
        int cx1 = clamp((int) Math.floor((x1 - minX) / cell), nx);
        int cy0 = clamp((int) Math.floor((y0 - minY) / cell), ny);
        int cy1 = clamp((int) Math.floor((y1 - minY) / cell), ny);
        double min = bound;
        for (int cy = cy0; cy <= cy1; cy++) {
            for (int cx = cx0; cx <= cx1; cx++) {
                int c = cy * nx + cx;
                for (int k = start[c]; k < start[c + 1]; k++) {
                    min = Math.min(min, distance.applyAsDouble(fixtures[items[k]].getUserData()));
                }
            }
        }
        return min;
    }

    /** @return how many static fixtures the grid holds */
    int fixtureCount() {
        return fixtures.length;
    }

    /**
     * One caller's scratch for ray casts (not shared between threads); the last hit's details are in
     * {@link #raycast()}.
     */
    final class Query {
        private final Raycast raycast = new Raycast();
        /** The fixtures cast against by the current ray (a fixture may lie in several of its cells). */
        private final int[] seen = new int[64];
        private int seenCount;

        /** @return the last hit found by {@link #closest} */
        Raycast raycast() {
            return raycast;
        }

        /**
         * The nearest static fixture along the ray, as dyn4j's {@code raycastClosest} over the static bodies.
         *
         * @param ray       the ray (unit direction)
         * @param maxLength how far to look, metres (greater than 0)
         * @return the hit's distance along the ray, metres, or -1 when nothing static lies within maxLength
         */
        double closest(Ray ray, double maxLength) {
            Vector2 s = ray.getStart();
            Vector2 d = ray.getDirectionVector();
            double sx = s.x;
            double sy = s.y;
            double dx = d.x;
            double dy = d.y;
            // Clip the ray to the grid's box.
            double t0 = 0.0;
            double t1 = maxLength + MARGIN_M;
            if (dx != 0.0) {
                double ta = (minX - sx) / dx;
                double tb = (maxX - sx) / dx;
                t0 = Math.max(t0, Math.min(ta, tb));
                t1 = Math.min(t1, Math.max(ta, tb));
            } else if (sx < minX || sx > maxX) {
                return -1.0;
            }
            if (dy != 0.0) {
                double ta = (minY - sy) / dy;
                double tb = (maxY - sy) / dy;
                t0 = Math.max(t0, Math.min(ta, tb));
                t1 = Math.min(t1, Math.max(ta, tb));
            } else if (sy < minY || sy > maxY) {
                return -1.0;
            }
            if (t0 > t1 || fixtures.length == 0) {
                return -1.0;
            }
            int cx = clamp((int) Math.floor((sx + t0 * dx - minX) / cell), nx);
            int cy = clamp((int) Math.floor((sy + t0 * dy - minY) / cell), ny);
            int stepX = dx > 0.0 ? 1 : dx < 0.0 ? -1 : 0;
            int stepY = dy > 0.0 ? 1 : dy < 0.0 ? -1 : 0;
            // Ray parameter at which the ray leaves the current cell across x and across y, and per cell.
            double tMaxX = stepX == 0 ? Double.POSITIVE_INFINITY : (minX + (cx + (stepX > 0 ? 1 : 0)) * cell - sx) / dx;
            double tMaxY = stepY == 0 ? Double.POSITIVE_INFINITY : (minY + (cy + (stepY > 0 ? 1 : 0)) * cell - sy) / dy;
            double tDeltaX = stepX == 0 ? Double.POSITIVE_INFINITY : cell / Math.abs(dx);
            double tDeltaY = stepY == 0 ? Double.POSITIVE_INFINITY : cell / Math.abs(dy);
            double best = maxLength;
            boolean found = false;
            seenCount = 0;
            double tEntry = t0;
            while (tEntry <= best + MARGIN_M && tEntry <= t1) {
                int c = cy * nx + cx;
                for (int k = start[c], end = start[c + 1]; k < end; k++) {
                    int item = items[k];
                    if (seenBefore(item) || !crossesBox(item, sx, sy, dx, dy, best + MARGIN_M)) {
                        continue;
                    }
                    // The same call and bound as dyn4j's raycastClosest: the bound shrinks to each hit found.
                    if (detector.raycast(ray, best, fixtures[item].getShape(), bodies[item].getTransform(), raycast)) {
                        best = raycast.getDistance();
                        found = true;
                    }
                }
                if (tMaxX < tMaxY) {
                    tEntry = tMaxX;
                    tMaxX += tDeltaX;
                    cx += stepX;
                    if (cx < 0 || cx >= nx) {
                        break;
                    }
                } else {
                    tEntry = tMaxY;
                    tMaxY += tDeltaY;
                    cy += stepY;
                    if (cy < 0 || cy >= ny) {
                        break;
                    }
                }
            }
            return found ? best : -1.0;
        }

        /** Whether the ray from (sx, sy) along (dx, dy) meets the item's grown box before length (slab test). */
        private boolean crossesBox(int item, double sx, double sy, double dx, double dy, double length) {
            int b = 4 * item;
            double lo = 0.0;
            double hi = length;
            if (dx != 0.0) {
                double ta = (boxes[b] - sx) / dx;
                double tb = (boxes[b + 2] - sx) / dx;
                lo = Math.max(lo, Math.min(ta, tb));
                hi = Math.min(hi, Math.max(ta, tb));
            } else if (sx < boxes[b] || sx > boxes[b + 2]) {
                return false;
            }
            if (dy != 0.0) {
                double ta = (boxes[b + 1] - sy) / dy;
                double tb = (boxes[b + 3] - sy) / dy;
                lo = Math.max(lo, Math.min(ta, tb));
                hi = Math.min(hi, Math.max(ta, tb));
            } else if (sy < boxes[b + 1] || sy > boxes[b + 3]) {
                return false;
            }
            return lo <= hi;
        }

        private boolean seenBefore(int item) {
            for (int i = 0; i < seenCount; i++) {
                if (seen[i] == item) {
                    return true;
                }
            }
            if (seenCount < seen.length) {
                seen[seenCount++] = item;
            }
            return false;
        }
    }
}
