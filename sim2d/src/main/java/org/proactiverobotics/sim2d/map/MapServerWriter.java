package org.proactiverobotics.sim2d.map;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes a grid as a ROS map_server map, as map_server's saver does: a raw PGM (P5) beside a YAML, free
 * cells 254, blocked cells 0, trinary mode and the saver's thresholds; the picture's top row is the
 * grid's last. What {@link MapServerMap} reads back to the same grid.
 */
public final class MapServerWriter {

    /** The grey of a free cell. */
    public static final int FREE = 254;
    /** The grey of a blocked cell. */
    public static final int OCCUPIED = 0;

    private MapServerWriter() {
    }

    /**
     * @param grid the map
     * @param yaml the YAML to write; the picture goes beside it, named as the YAML with {@code .pgm}
     * @return the picture's path
     * @throws IOException when a file cannot be written
     */
    public static Path write(OccupancyGrid grid, Path yaml) throws IOException {
        String base = yaml.getFileName().toString().replaceFirst("\\.ya?ml$", "");
        Path pgm = yaml.resolveSibling(base + ".pgm");
        int w = grid.columns();
        int h = grid.rows();
        byte[] header = String.format(Locale.ROOT, "P5\n# written by proactive-robotics\n%d %d\n255\n", w, h)
                .getBytes(StandardCharsets.US_ASCII);
        byte[] bytes = new byte[header.length + w * h];
        System.arraycopy(header, 0, bytes, 0, header.length);
        for (int r = 0; r < h; r++) {
            int j = h - 1 - r;
            for (int i = 0; i < w; i++) {
                bytes[header.length + r * w + i] = (byte) (grid.blocked(i, j) ? OCCUPIED : FREE);
            }
        }
        Files.write(pgm, bytes);
        Files.writeString(yaml, String.format(Locale.ROOT, "image: %s%nresolution: %s%norigin: [%s, %s, 0.0]%nnegate: 0%n"
                        + "occupied_thresh: 0.65%nfree_thresh: 0.196%nmode: trinary%n", pgm.getFileName(), grid.cellM(),
                grid.originX(), grid.originY()), StandardCharsets.UTF_8);
        return pgm;
    }
}
