package org.proactiverobotics.sim2d.map;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;

/**
 * Reads a grid map of the Moving AI path-finding benchmarks: the lines {@code type octile},
 * {@code height H}, {@code width W}, {@code map}, then H rows of W characters, the first row the
 * map's top. {@code .}, {@code G} and {@code S} are free; {@code @}, {@code O}, {@code T} and {@code W}
 * are blocked; anything else is refused. The map's lower-left corner is put at (0, 0).
 */
public final class MovingAiMap {

    private static final String FREE = ".GS";
    private static final String BLOCKED = "@OTW";

    private MovingAiMap() {
    }

    /**
     * @param file  a {@code .map} file
     * @param cellM metres a cell, &gt; 0
     * @return the map
     * @throws MapException naming the file and the problem
     */
    public static MapReading read(Path file, double cellM) {
        if (!(cellM > 0) || Double.isInfinite(cellM)) {
            throw new MapException(file, "the cell size must be > 0 metres, got " + cellM);
        }
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.ISO_8859_1).stream().map(MovingAiMap::chomp).toList();
        } catch (NoSuchFileException e) {
            throw new MapException(file, "no such file");
        } catch (IOException e) {
            throw new MapException(file, "cannot read it: " + e.getMessage());
        }
        if (lines.size() < 4) {
            throw new MapException(file, "not a Moving AI map: expected the lines type, height, width and map first");
        }
        String[] type = lines.get(0).trim().split("\\s+");
        if (type.length != 2 || !type[0].equals("type")) {
            throw new MapException(file, "wrong first line: expected \"type octile\", got \"" + lines.get(0) + "\"");
        }
        if (!type[1].equals("octile")) {
            throw new MapException(file, "type " + type[1] + " is not read: only octile maps");
        }
        int height = header(file, lines.get(1), "height");
        int width = header(file, lines.get(2), "width");
        if (!lines.get(3).trim().equals("map")) {
            throw new MapException(file, "line 4: expected \"map\", got \"" + lines.get(3) + "\"");
        }
        if ((long) width * height > MapImage.MAX_PIXELS) {
            throw new MapException(file, width + " x " + height + " cells, more than the " + MapImage.MAX_PIXELS + " a map may have");
        }
        List<String> rows = lines.subList(4, lines.size());
        int last = rows.size();
        while (last > 0 && rows.get(last - 1).isEmpty()) {
            last--; // blank lines at the end are no rows
        }
        if (last != height) {
            throw new MapException(file, "the header says height " + height + " but the map has " + last + " rows");
        }
        boolean[] blocked = new boolean[width * height];
        for (int r = 0; r < height; r++) {
            String row = rows.get(r);
            if (row.length() != width) {
                throw new MapException(file, "row " + (r + 1) + " has " + row.length() + " cells, the header says width " + width);
            }
            int j = height - 1 - r;
            for (int i = 0; i < width; i++) {
                char c = row.charAt(i);
                if (BLOCKED.indexOf(c) >= 0) {
                    blocked[j * width + i] = true;
                } else if (FREE.indexOf(c) < 0) {
                    throw new MapException(file, "row " + (r + 1) + ", column " + (i + 1) + ": '" + c
                            + "' is no terrain of a Moving AI map (. G S free, @ O T W blocked)");
                }
            }
        }
        return new MapReading(new OccupancyGrid(width, height, cellM, 0.0, 0.0, blocked), List.of());
    }

    private static int header(Path file, String line, String key) {
        String[] parts = line.trim().split("\\s+");
        if (parts.length != 2 || !parts[0].equals(key)) {
            throw new MapException(file, "expected \"" + key + " N\", got \"" + line + "\"");
        }
        try {
            int v = Integer.parseInt(parts[1]);
            if (v < 1) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new MapException(file, key + " must be a whole number from 1, got " + parts[1]);
        }
    }

    private static String chomp(String line) {
        return line.endsWith("\r") ? line.substring(0, line.length() - 1) : line;
    }
}
