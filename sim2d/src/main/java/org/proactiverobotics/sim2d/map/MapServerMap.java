package org.proactiverobotics.sim2d.map;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.Yaml;
import org.yaml.snakeyaml.constructor.SafeConstructor;
import org.yaml.snakeyaml.error.YAMLException;

/**
 * Reads a ROS map_server map (its YAML and the picture it names) as map_server reads it, then keeps
 * only what a world needs: a cell is free floor when map_server would mark it free (0), blocked
 * otherwise (occupied, unknown, or in scale mode a value between the thresholds).
 * <p>
 * The YAML's keys: {@code image} (relative to the YAML's folder), {@code resolution} (metres a pixel),
 * {@code origin} ([x, y, yaw] of the picture's lower-left corner; the yaw must be 0), and optionally
 * {@code negate} (0 or 1, default 0), {@code occupied_thresh} (default 0.65), {@code free_thresh}
 * (default 0.196) and {@code mode} ({@code trinary} (default), {@code scale} or {@code raw}). Any other
 * key is refused. A pixel's shade is the mean of its channels (alpha included in trinary mode, as
 * map_server averages), turned over by {@code negate}; in trinary and scale mode its occupancy is
 * p = (255 - shade) / 255 and it is free when p &lt; free_thresh (occupied when p &gt; occupied_thresh,
 * unknown between); in raw mode the shade is the value and only 0 is free.
 */
public final class MapServerMap {

    /** map_server's trinary default, and the mode when the YAML gives none. */
    public static final String TRINARY = "trinary";
    /** The thresholds map_server writes when saving a map. */
    public static final double DEFAULT_OCCUPIED_THRESH = 0.65;
    /** The free threshold map_server writes when saving a map. */
    public static final double DEFAULT_FREE_THRESH = 0.196;
    /** The grey map_server writes for unknown cells, 0–255. */
    static final int UNKNOWN_GREY = 205;

    private static final Set<String> KEYS = Set.of("image", "resolution", "origin", "negate", "occupied_thresh",
            "free_thresh", "mode");
    private static final Set<String> MODES = Set.of("trinary", "scale", "raw");

    private MapServerMap() {
    }

    /**
     * @param yamlFile the map's YAML
     * @return the map
     * @throws MapException naming the YAML or the picture, and the problem
     */
    public static MapReading read(Path yamlFile) {
        String text;
        try {
            text = Files.readString(yamlFile);
        } catch (NoSuchFileException e) {
            throw new MapException(yamlFile, "no such file");
        } catch (IOException | java.io.UncheckedIOException e) {
            throw new MapException(yamlFile, "cannot read it: " + e.getMessage());
        }
        Object root;
        try {
            root = new Yaml(new SafeConstructor(new LoaderOptions())).load(text);
        } catch (YAMLException e) {
            throw new MapException(yamlFile, "not valid YAML: " + e.getMessage().lines().findFirst().orElse(""));
        }
        if (!(root instanceof Map<?, ?> map)) {
            throw new MapException(yamlFile, "expected a map_server YAML (image, resolution, origin, ...), got "
                    + (root == null ? "an empty file" : "no mapping of keys"));
        }
        TreeSet<String> unknown = new TreeSet<>();
        map.keySet().forEach(k -> {
            if (!KEYS.contains(String.valueOf(k))) {
                unknown.add(String.valueOf(k));
            }
        });
        if (!unknown.isEmpty()) {
            throw new MapException(yamlFile, "unknown key" + (unknown.size() == 1 ? " " : "s ") + String.join(", ", unknown)
                    + " (a map_server YAML has " + String.join(", ", new TreeSet<>(KEYS)) + ")");
        }
        Object image = map.get("image");
        if (!(image instanceof String imageName) || imageName.isBlank()) {
            throw new MapException(yamlFile, image == null ? "image: missing required key" : "image: expected a file name, got " + image);
        }
        double resolution = number(yamlFile, map, "resolution", null);
        if (!(resolution > 0)) {
            throw new MapException(yamlFile, "resolution: must be > 0 (metres a pixel), got " + format(resolution));
        }
        double[] origin = origin(yamlFile, map.get("origin"));
        boolean negate = negate(yamlFile, map.get("negate"));
        double occupied = number(yamlFile, map, "occupied_thresh", DEFAULT_OCCUPIED_THRESH);
        double free = number(yamlFile, map, "free_thresh", DEFAULT_FREE_THRESH);
        for (String key : List.of("occupied_thresh", "free_thresh")) {
            double v = key.equals("free_thresh") ? free : occupied;
            if (!(v >= 0 && v <= 1)) {
                throw new MapException(yamlFile, key + ": must be from 0 to 1, got " + format(v));
            }
        }
        if (free > occupied) {
            throw new MapException(yamlFile, "free_thresh (" + format(free) + ") must not be above occupied_thresh ("
                    + format(occupied) + ")");
        }
        Object modeValue = map.get("mode");
        String mode = modeValue == null ? TRINARY : String.valueOf(modeValue);
        if (!MODES.contains(mode)) {
            throw new MapException(yamlFile, "mode: must be trinary, scale or raw, got " + mode);
        }
        Path imageFile = yamlFile.toAbsolutePath().getParent().resolve(imageName);
        return grid(imageFile, resolution, origin, negate, occupied, free, mode);
    }

    /**
     * A picture without its YAML (a Stage bitmap, a floor plan drawn by hand) read as map_server reads
     * one whose YAML gives only the image and its resolution: origin (0, 0), not negated, the default
     * thresholds, trinary.
     *
     * @param picture        the PGM or PNG
     * @param metresAPixel   the picture's resolution, metres a pixel
     * @return the map
     * @throws MapException naming the picture and the problem
     */
    public static MapReading readPicture(Path picture, double metresAPixel) {
        return grid(picture, metresAPixel, new double[] {0, 0}, false, DEFAULT_OCCUPIED_THRESH, DEFAULT_FREE_THRESH, TRINARY);
    }

    private static MapReading grid(Path imageFile, double resolution, double[] origin, boolean negate, double occupied,
                                   double free, String mode) {
        MapImage picture = MapImage.read(imageFile);
        double[] mean = mode.equals(TRINARY) ? picture.meanWithAlpha() : picture.meanWithoutAlpha();
        int w = picture.width();
        int h = picture.height();
        boolean[] blocked = new boolean[w * h];
        boolean raw = mode.equals("raw");
        for (int r = 0; r < h; r++) {
            int j = h - 1 - r; // the picture's top row is the map's last
            for (int i = 0; i < w; i++) {
                double shade = mean[r * w + i];
                if (negate) {
                    shade = 255.0 - shade;
                }
                boolean isFree = raw ? shade < 1.0 : (255.0 - shade) / 255.0 < free;
                blocked[j * w + i] = !isFree;
            }
        }
        List<String> notes = new ArrayList<>();
        double unknownP = (255.0 - UNKNOWN_GREY) / 255.0;
        if (!raw && !negate && free > unknownP) {
            notes.add(String.format(Locale.ROOT, "free_thresh %s reads map_server's unknown grey (%d, p = %.3f) as free floor:"
                    + " a map saved with unknown cells has open floor where nothing was seen", format(free), UNKNOWN_GREY, unknownP));
        }
        return new MapReading(new OccupancyGrid(w, h, resolution, origin[0], origin[1], blocked), notes);
    }

    private static double[] origin(Path file, Object value) {
        if (value == null) {
            throw new MapException(file, "origin: missing required key");
        }
        if (!(value instanceof List<?> list) || list.size() != 3 || !list.stream().allMatch(MapServerMap::isNumber)) {
            throw new MapException(file, "origin: expected [x, y, yaw], three numbers, got " + value);
        }
        double[] o = list.stream().mapToDouble(v -> ((Number) v).doubleValue()).toArray();
        if (!Double.isFinite(o[0]) || !Double.isFinite(o[1]) || !Double.isFinite(o[2])) {
            throw new MapException(file, "origin: must be finite numbers, got " + value);
        }
        if (o[2] != 0.0) {
            throw new MapException(file, "origin: the yaw must be 0 (a rotated map is not read), got " + format(o[2]));
        }
        return o;
    }

    private static boolean negate(Path file, Object value) {
        if (value == null) {
            return false;
        }
        if (value instanceof Boolean b) {
            return b;
        }
        if (value instanceof Integer i && (i == 0 || i == 1)) {
            return i == 1;
        }
        throw new MapException(file, "negate: must be 0 or 1, got " + value);
    }

    private static double number(Path file, Map<?, ?> map, String key, Double dflt) {
        Object v = map.get(key);
        if (v == null) {
            if (dflt == null) {
                throw new MapException(file, key + ": missing required key");
            }
            return dflt;
        }
        if (!isNumber(v)) {
            throw new MapException(file, key + ": expected a number, got " + v);
        }
        double d = ((Number) v).doubleValue();
        if (!Double.isFinite(d)) {
            throw new MapException(file, key + ": must be a finite number, got " + v);
        }
        return d;
    }

    private static boolean isNumber(Object v) {
        return v instanceof Number;
    }

    private static String format(double v) {
        return String.valueOf(v);
    }
}
