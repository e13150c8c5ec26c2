package org.proactiverobotics.sim2d.map;

import java.nio.file.Path;
import java.util.Locale;

/**
 * Reads a map by its kind, told by the file's name: a ROS map_server YAML ({@code .yaml}, {@code .yml}),
 * a Moving AI grid map ({@code .map}), or a picture alone ({@code .pgm}, {@code .png}: a Stage bitmap,
 * read as map_server reads one, at a resolution the caller gives).
 */
public final class MapFiles {

    /** Metres a cell of a Moving AI map when nothing else is said. */
    public static final double DEFAULT_CELL_M = 0.5;

    private MapFiles() {
    }

    /**
     * @param file  the map
     * @param cellM metres a cell for a Moving AI map or a picture alone (a map_server YAML gives its own resolution)
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
        if (isPicture(file)) {
            return MapServerMap.readPicture(file, cellM);
        }
        throw new MapException(file, "not a map this reads: give a ROS map_server YAML (.yaml), a Moving AI map (.map),"
                + " or a picture (.pgm, .png) with its metres a pixel");
    }

    /** @return whether the file is named as a picture alone (PGM or PNG), whose scale the caller must give */
    public static boolean isPicture(Path file) {
        String n = name(file);
        return n.endsWith(".pgm") || n.endsWith(".png");
    }

    /** @return whether the file's own contents do not give its cell size (a Moving AI map, a picture alone) */
    public static boolean takesCellSize(Path file) {
        return isMovingAi(file) || isPicture(file);
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
