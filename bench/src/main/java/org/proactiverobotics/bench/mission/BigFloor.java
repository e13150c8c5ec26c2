package org.proactiverobotics.bench.mission;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * A building floor for the benchmarks, as a SLAM map of one merges into boxes: a grid of rooms
 * about {@value #ROOM_M} m across, each wall between two rooms with a door of {@value #DOOR_M} m,
 * every wall cut into short boxes of uneven thickness (as merged occupied cells come out), and
 * furniture along the walls, clear of the doors. The robot starts in a corner room, three
 * checkpoints lie in rooms far across the floor, the station beside the start; the battery drains
 * a fifth of a percent a metre, so that the long ways do not run it flat. Seeded: the same size
 * and seed give the same floor. Built as world-file text, so that it is read as any world is.
 */
public final class BigFloor {

    /** A room's size, metres (the floor is divided into whole rooms about this size). */
    static final double ROOM_M = 5.0;
    /** A door's width, metres. */
    static final double DOOR_M = 1.0;
    /** A wall's thickness, metres (each box a little more or less). */
    static final double WALL_M = 0.1;

    private final double widthM;
    private final double heightM;
    private final SplittableRandom random;
    private final StringBuilder obstacles = new StringBuilder();
    private int boxes;
    /** Furniture placed so far, x0 y0 x1 y1 each, metres. */
    private final List<double[]> furniture = new ArrayList<>();
    /** Door centres, x y each, metres. */
    private final List<double[]> doors = new ArrayList<>();

    private BigFloor(double widthM, double heightM, long seed) {
        this.widthM = widthM;
        this.heightM = heightM;
        this.random = new SplittableRandom(seed);
    }

    /**
     * @param widthM  the floor's width, metres
     * @param heightM its height, metres
     * @param seed    the seed of its walls' unevenness, doors and furniture
     * @return the floor as a world
     */
    public static WorldSpec world(double widthM, double heightM, long seed) {
        return WorldFiles.parse(json(widthM, heightM, seed), "big floor");
    }

    /** @return the floor as world-file text */
    static String json(double widthM, double heightM, long seed) {
        return new BigFloor(widthM, heightM, seed).build(seed);
    }

    private String build(long seed) {
        int cols = Math.max(2, (int) Math.round(widthM / ROOM_M));
        int rows = Math.max(2, (int) Math.round(heightM / ROOM_M));
        double rw = widthM / cols;
        double rh = heightM / rows;
        double x0 = -widthM / 2;
        double y0 = -heightM / 2;
        // the outside walls, closed
        wall(x0, y0, x0 + widthM, y0, false);
        wall(x0, y0 + heightM, x0 + widthM, y0 + heightM, false);
        wall(x0, y0, x0, y0 + heightM, false);
        wall(x0 + widthM, y0, x0 + widthM, y0 + heightM, false);
        // the walls between rooms, a door in each
        for (int c = 1; c < cols; c++) {
            for (int r = 0; r < rows; r++) {
                wall(x0 + c * rw, y0 + r * rh, x0 + c * rw, y0 + (r + 1) * rh, true);
            }
        }
        for (int r = 1; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                wall(x0 + c * rw, y0 + r * rh, x0 + (c + 1) * rw, y0 + r * rh, true);
            }
        }
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                furnish(x0 + c * rw, y0 + r * rh, rw, rh);
            }
        }
        double sx = x0 + rw / 2;
        double sy = y0 + rh / 2;
        String[] cps = {
            point(x0 + (cols - 0.5) * rw, y0 + (rows - 0.5) * rh),
            point(x0 + (cols - 0.5) * rw, y0 + 0.5 * rh),
            point(x0 + (cols / 2 + 0.5) * rw, y0 + (rows / 2 + 0.5) * rh),
        };
        double arenaR = Math.hypot(widthM, heightM) / 2 + 1.0;
        return String.format(Locale.ROOT, """
                { "name": "big-floor-%dx%d", "maxSimTimeS": 3600, "seed": %d, "arena": {"radiusM": %.3f},
                  "robot": {"x": %.3f, "y": %.3f, "headingDeg": 0},
                  "obstacles": [%s],
                  "checkpoints": [%s, %s, %s],
                  "rechargeStation": {"x": %.3f, "y": %.3f, "radiusM": 0.35},
                  "battery": {"initial": 100, "drainPerMeter": 0.2, "rechargeTo": 100, "rechargeRatePerS": 10} }
                """, Math.round(widthM), Math.round(heightM), seed, arenaR, sx, sy, obstacles, cps[0], cps[1], cps[2],
                sx - 1.2, sy - 1.2);
    }

    /** @return how many boxes the floor has (after {@link #build}) */
    int boxes() {
        return boxes;
    }

    private static String point(double x, double y) {
        return String.format(Locale.ROOT, "{\"x\": %.3f, \"y\": %.3f}", x, y);
    }

    /** A wall from (ax, ay) to (bx, by), axis-aligned, cut into boxes of 0.3 to 0.8 m; with a door, one gap of {@value #DOOR_M} m. */
    private void wall(double ax, double ay, double bx, double by, boolean door) {
        boolean vertical = ax == bx;
        double from = vertical ? ay : ax;
        double to = vertical ? by : bx;
        double doorAt = door ? from + 0.8 + random.nextDouble() * (to - from - 1.6 - DOOR_M) : Double.NaN;
        if (door) {
            doors.add(vertical ? new double[] {ax, doorAt + DOOR_M / 2} : new double[] {doorAt + DOOR_M / 2, ay});
        }
        double at = from;
        while (at < to - 1e-9) {
            double end = Math.min(to, at + 0.3 + random.nextDouble() * 0.5);
            if (door && end > doorAt && at < doorAt + DOOR_M) {
                end = doorAt; // the piece up to the door, then skip the door
                if (end - at > 1e-6) {
                    piece(vertical, vertical ? ax : ay, at, end);
                }
                at = doorAt + DOOR_M;
                continue;
            }
            piece(vertical, vertical ? ax : ay, at, end);
            at = end;
        }
    }

    /** One box of a wall: along the wall from {@code a} to {@code b} at {@code across}, of uneven thickness. */
    private void piece(boolean vertical, double across, double a, double b) {
        double thick = WALL_M * (0.8 + 0.4 * random.nextDouble());
        double shift = (random.nextDouble() - 0.5) * 0.02;
        double len = b - a;
        if (len < 0.005) {
            return; // a sliver at a wall's end: nothing a body could pass
        }
        double mid = (a + b) / 2;
        box(vertical ? across + shift : mid, vertical ? mid : across + shift, vertical ? thick : len, vertical ? len : thick);
    }

    /** Three to seven pieces of furniture against a room's walls, clear of the doors and of each other. */
    private void furnish(double rx, double ry, double rw, double rh) {
        int n = 3 + random.nextInt(5);
        for (int tries = 0; tries < 40 && n > 0; tries++) {
            double w = 0.3 + random.nextDouble() * 0.7;
            double h = 0.3 + random.nextDouble() * 0.5;
            int side = random.nextInt(4);
            double x;
            double y;
            if (side < 2) {
                x = rx + 0.3 + w / 2 + random.nextDouble() * (rw - 0.6 - w);
                y = side == 0 ? ry + 0.15 + h / 2 : ry + rh - 0.15 - h / 2;
            } else {
                double t = w;
                w = h;
                h = t;
                y = ry + 0.3 + h / 2 + random.nextDouble() * (rh - 0.6 - h);
                x = side == 2 ? rx + 0.15 + w / 2 : rx + rw - 0.15 - w / 2;
            }
            if (nearDoor(x, y, Math.max(w, h) / 2 + 1.0) || overlapsFurniture(x, y, w, h)) {
                continue;
            }
            furniture.add(new double[] {x - w / 2 - 0.5, y - h / 2 - 0.5, x + w / 2 + 0.5, y + h / 2 + 0.5});
            box(x, y, w, h);
            n--;
        }
    }

    private boolean nearDoor(double x, double y, double m) {
        for (double[] d : doors) {
            if (Math.abs(d[0] - x) < m && Math.abs(d[1] - y) < m) {
                return true;
            }
        }
        return false;
    }

    /** Whether a box comes within half a metre of furniture already placed (so a way stays between them). */
    private boolean overlapsFurniture(double x, double y, double w, double h) {
        for (double[] f : furniture) {
            if (x + w / 2 > f[0] && x - w / 2 < f[2] && y + h / 2 > f[1] && y - h / 2 < f[3]) {
                return true;
            }
        }
        return false;
    }

    private void box(double x, double y, double w, double h) {
        if (boxes > 0) {
            obstacles.append(",\n    ");
        }
        obstacles.append(String.format(Locale.ROOT,
                "{\"shape\": \"box\", \"x\": %.4f, \"y\": %.4f, \"widthM\": %.4f, \"heightM\": %.4f, \"angleDeg\": 0}", x, y, w, h));
        boxes++;
    }

    /**
     * Writes a floor's world file: {@code BigFloor WIDTH HEIGHT SEED FILE}.
     *
     * @param args width and height (metres), seed, and the file to write
     * @throws Exception when the file cannot be written
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 4) {
            System.err.println("usage: BigFloor WIDTH_M HEIGHT_M SEED FILE");
            System.exit(2);
        }
        String text = json(Double.parseDouble(args[0]), Double.parseDouble(args[1]), Long.parseLong(args[2]));
        WorldSpec w = WorldFiles.parse(text, args[3]);
        java.nio.file.Files.writeString(java.nio.file.Path.of(args[3]), text);
        System.out.printf(Locale.ROOT, "%s: %d obstacles, %.0f x %.0f m%n", args[3], w.obstacles().size(),
                Double.parseDouble(args[0]), Double.parseDouble(args[1]));
    }
}
