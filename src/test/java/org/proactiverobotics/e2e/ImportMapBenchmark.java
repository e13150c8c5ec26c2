package org.proactiverobotics.e2e;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;
import org.proactiverobotics.sim2d.map.MapServerWriter;
import org.proactiverobotics.sim2d.map.OccupancyGrid;

/**
 * A benchmark, not a test (it asserts nothing and runs only when asked): how long {@code import-map}
 * takes on a floor of 2 000 x 2 000 pixels (100 x 100 m at 0.05 m), from the command's start in a JVM
 * of its own to its exit, median of three. The floor is drawn here from a seed: about 400 rooms of 4 to
 * 6 m with 0.15 m walls and 0.9 m doors, furniture and single-pixel speckle, the outside a ragged
 * band of walls. Run it (docs/maps.md):
 * {@code ./mvnw -q -o -pl e2e -am verify -Dtest=ImportMapBenchmark -Dsurefire.failIfNoSpecifiedTests=false
 * -Dimport.bench=/tmp/import-bench}
 */
class ImportMapBenchmark {

    /** Pixels a side. */
    static final int SIDE = 2000;

    @Test
    @EnabledIfSystemProperty(named = "import.bench", matches = ".+")
    void importABigFloorThreeTimes() throws Exception {
        Path dir = Files.createDirectories(Path.of(System.getProperty("import.bench")));
        Path yaml = dir.resolve("floor-100m.yaml");
        MapServerWriter.write(floor(SIDE, 3), yaml);
        List<Double> seconds = new ArrayList<>();
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        for (int k = 0; k < 3; k++) {
            Path out = dir.resolve("floor-100m.json");
            long t0 = System.nanoTime();
            Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "org.proactiverobotics.app.Main",
                    "import-map", "--map", yaml.toString(), "--out", out.toString(), "--force").inheritIO().start();
            if (!p.waitFor(120, TimeUnit.SECONDS) || p.exitValue() != 0) {
                throw new IllegalStateException("import-map failed");
            }
            seconds.add((System.nanoTime() - t0) / 1e9);
        }
        System.out.printf(Locale.ROOT, "import-map of %d x %d px: %s s (median %.2f s)%n", SIDE, SIDE, seconds,
                seconds.stream().sorted().toList().get(1));
    }

    /** A building floor of rooms off a grid of walls, drawn from the seed; free 254 cells inside, walls round. */
    static OccupancyGrid floor(int side, long seed) throws IOException {
        SplittableRandom random = new SplittableRandom(seed);
        boolean[] blocked = new boolean[side * side];
        int margin = side / 20;
        fill(blocked, side, 0, 0, side, side, true);
        fill(blocked, side, margin + 3, margin + 3, side - margin - 3, side - margin - 3, false);
        for (int y = margin + 3; y < side - margin - 3; ) {
            int rh = 80 + random.nextInt(41);
            fill(blocked, side, margin, y + rh, side - margin, y + rh + 3, true);
            for (int x = margin + 3; x < side - margin - 3; ) {
                int rw = 80 + random.nextInt(41);
                fill(blocked, side, x + rw, y, x + rw + 3, y + rh, true);
                int d = y + 5 + random.nextInt(Math.max(1, rh - 30));
                fill(blocked, side, x + rw, d, x + rw + 3, d + 18, false); // a door to the next room
                d = x + 5 + random.nextInt(Math.max(1, rw - 30));
                fill(blocked, side, d, y + rh, d + 18, y + rh + 3, false); // and one to the room above
                for (int f = 0; f < 3; f++) { // furniture
                    int fx = x + 10 + random.nextInt(Math.max(1, rw - 40));
                    int fy = y + 10 + random.nextInt(Math.max(1, rh - 40));
                    fill(blocked, side, fx, fy, fx + 5 + random.nextInt(16), fy + 5 + random.nextInt(16), true);
                }
                for (int s = 0; s < 10; s++) { // speckle
                    int sx = x + 2 + random.nextInt(Math.max(1, rw - 4));
                    int sy = y + 2 + random.nextInt(Math.max(1, rh - 4));
                    fill(blocked, side, sx, sy, sx + 1, sy + 1, true);
                }
                x += rw + 3;
            }
            y += rh + 3;
        }
        // whatever the rooms' grid left open beyond the outer walls is closed again
        fill(blocked, side, 0, 0, side, margin + 3, true);
        fill(blocked, side, 0, side - margin - 3, side, side, true);
        fill(blocked, side, 0, 0, margin + 3, side, true);
        fill(blocked, side, side - margin - 3, 0, side, side, true);
        for (int k = 0; k < 4000; k++) { // ragged free pockets in the outside band, as a scan leaves them
            int sx = random.nextInt(side);
            int sy = random.nextInt(margin - 2);
            fill(blocked, side, sx, sy + 1, Math.min(side, sx + 1 + random.nextInt(6)), sy + 2, false);
        }
        return new OccupancyGrid(side, side, 0.05, -side * 0.025, -side * 0.025, blocked);
    }

    private static void fill(boolean[] cells, int side, int x0, int y0, int x1, int y1, boolean value) {
        for (int y = Math.max(0, y0); y < Math.min(side, y1); y++) {
            for (int x = Math.max(0, x0); x < Math.min(side, x1); x++) {
                cells[y * side + x] = value;
            }
        }
    }
}
