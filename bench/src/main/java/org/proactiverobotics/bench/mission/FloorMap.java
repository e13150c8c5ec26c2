package org.proactiverobotics.bench.mission;

import java.nio.file.Path;
import java.util.Locale;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.map.MapServerWriter;
import org.proactiverobotics.sim2d.map.OccupancyGrid;
import org.proactiverobotics.sim2d.map.WorldRaster;

/**
 * A {@link BigFloor} drawn as a ROS map_server map (a P5 PGM beside its YAML), the kind of file
 * {@code import-map} reads: the floor's walls and furniture rasterised at a given cell size, every
 * cell outside the building's outer walls blocked (a SLAM map's unknown outside). For the sweeps of
 * missions on imported maps (docs/maps.md): the maps are made again from the size and seed rather
 * than kept in the repository.
 */
public final class FloorMap {

    /** Cells of margin round the building, so that the outer walls lie inside the picture. */
    static final int MARGIN_CELLS = 3;

    private FloorMap() {
    }

    /**
     * @param widthM  the floor's width, metres
     * @param heightM its height, metres
     * @param seed    the floor's seed ({@link BigFloor})
     * @param cellM   a cell's side, metres
     * @return the floor's map
     */
    static OccupancyGrid of(double widthM, double heightM, long seed, double cellM) {
        WorldSpec world = BigFloor.world(widthM, heightM, seed);
        int columns = (int) Math.ceil(widthM / cellM) + 2 * MARGIN_CELLS;
        int rows = (int) Math.ceil(heightM / cellM) + 2 * MARGIN_CELLS;
        double originX = -widthM / 2 - MARGIN_CELLS * cellM;
        double originY = -heightM / 2 - MARGIN_CELLS * cellM;
        OccupancyGrid raster = WorldRaster.of(world, cellM, originX, originY, columns, rows);
        boolean[] blocked = new boolean[columns * rows];
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < columns; i++) {
                double x = originX + (i + 0.5) * cellM;
                double y = originY + (j + 0.5) * cellM;
                boolean outside = Math.abs(x) > widthM / 2 || Math.abs(y) > heightM / 2;
                blocked[j * columns + i] = outside || raster.blocked(i, j);
            }
        }
        return new OccupancyGrid(columns, rows, cellM, originX, originY, blocked);
    }

    /**
     * Writes a floor's map: {@code FloorMap WIDTH_M HEIGHT_M SEED CELL_M FILE.yaml} (the PGM beside it).
     *
     * @param args width and height (metres), seed, cell size (metres), the YAML to write
     * @throws Exception when a file cannot be written
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 5) {
            System.err.println("usage: FloorMap WIDTH_M HEIGHT_M SEED CELL_M FILE.yaml");
            System.exit(2);
        }
        OccupancyGrid grid = of(Double.parseDouble(args[0]), Double.parseDouble(args[1]), Long.parseLong(args[2]),
                Double.parseDouble(args[3]));
        Path pgm = MapServerWriter.write(grid, Path.of(args[4]));
        System.out.printf(Locale.ROOT, "%s: %d x %d cells of %.3f m (%s)%n", args[4], grid.columns(), grid.rows(),
                grid.cellM(), pgm.getFileName());
    }
}
