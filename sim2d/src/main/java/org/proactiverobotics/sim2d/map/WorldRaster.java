package org.proactiverobotics.sim2d.map;

import org.proactiverobotics.sim2d.WorldSpec;

/**
 * A world drawn as a map: square cells over a region, a cell blocked when its centre lies inside an
 * obstacle or outside the arena. The way back from a world to the maps {@code import-map} reads
 * (rasterise a generated floor, write it with {@link MapServerWriter}, import it again).
 */
public final class WorldRaster {

    private WorldRaster() {
    }

    /**
     * @param world   the world
     * @param cellM   a cell's side, metres
     * @param originX x of the region's lower-left corner, metres
     * @param originY y of the region's lower-left corner, metres
     * @param columns cells along x
     * @param rows    cells along y
     * @return the cells
     */
    public static OccupancyGrid of(WorldSpec world, double cellM, double originX, double originY, int columns, int rows) {
        boolean[] blocked = new boolean[columns * rows];
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < columns; i++) {
                blocked[j * columns + i] = world.arena().inside(originX + (i + 0.5) * cellM, originY + (j + 0.5) * cellM) < 0;
            }
        }
        // each obstacle over the cells of its bounding square only: a floor has thousands of them
        for (WorldSpec.Obstacle o : world.obstacles()) {
            double reach = o.isCircle() ? o.radiusM() : Math.hypot(o.widthM(), o.heightM()) / 2;
            int i0 = Math.max(0, (int) Math.floor((o.x() - reach - originX) / cellM) - 1);
            int i1 = Math.min(columns - 1, (int) Math.ceil((o.x() + reach - originX) / cellM) + 1);
            int j0 = Math.max(0, (int) Math.floor((o.y() - reach - originY) / cellM) - 1);
            int j1 = Math.min(rows - 1, (int) Math.ceil((o.y() + reach - originY) / cellM) + 1);
            for (int j = j0; j <= j1; j++) {
                for (int i = i0; i <= i1; i++) {
                    if (!blocked[j * columns + i] && o.distanceTo(originX + (i + 0.5) * cellM, originY + (j + 0.5) * cellM) == 0.0) {
                        blocked[j * columns + i] = true;
                    }
                }
            }
        }
        return new OccupancyGrid(columns, rows, cellM, originX, originY, blocked);
    }

    /** @return whether the point (metres) is inside an obstacle or outside the arena */
    public static boolean blocked(WorldSpec world, double x, double y) {
        if (world.arena().inside(x, y) < 0) {
            return true;
        }
        for (WorldSpec.Obstacle o : world.obstacles()) {
            if (o.distanceTo(x, y) == 0.0) {
                return true;
            }
        }
        return false;
    }
}
