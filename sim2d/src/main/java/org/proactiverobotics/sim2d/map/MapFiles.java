package org.proactiverobotics.sim2d.map;

import java.nio.file.Path;
import java.util.Locale;

/**
 * Reads a map by its kind, told by the file's name: a ROS map_server YAML ({@code .yaml}, {@code .yml})
 * or a Moving AI grid map ({@code .map}).
 */
public final class MapFiles {

    /** Metres a cell of a Moving AI map when nothing else is said. */
    public static final double DEFAULT_CELL_M = 0.5;

    private MapFiles() {
    }

    /**
     * @param file  the map
     * @param cellM metres a cell for a Moving AI map (a map_server YAML gives its own resolution)
     * @return the map
     * @throws MapException naming the file and the problem
     */
    public static MapReading read(Path file, double cellM) {
        if (isMovingAi(file)) {
            return MovingAiMap.read(file, cellM);
        }
        if (isMapServer(file)) {
            return MapServerMap.read(file);
        }
        throw new MapException(file, "not a map this reads: give a ROS map_server YAML (.yaml) or a Moving AI map (.map)");
    }

    /** @return whether the file is named as a Moving AI map */
    public static boolean isMovingAi(Path file) {
        return name(file).endsWith(".map");
    }

    /** @return whether the file is named as a map_server YAML */
    public static boolean isMapServer(Path file) {
        String n = name(file);
        return n.endsWith(".yaml") || n.endsWith(".yml");
    }

    private static String name(Path file) {
        Path f = file.getFileName();
        return f == null ? "" : f.toString().toLowerCase(Locale.ROOT);
    }
}
