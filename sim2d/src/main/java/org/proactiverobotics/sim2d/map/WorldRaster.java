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
                double x = originX + (i + 0.5) * cellM;
                double y = originY + (j + 0.5) * cellM;
                blocked[j * columns + i] = blocked(world, x, y);
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
