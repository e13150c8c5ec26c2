package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.sim2d.map.BoxCover;
import org.proactiverobotics.sim2d.map.MapServerWriter;
import org.proactiverobotics.sim2d.map.OccupancyGrid;

/** Worlds that name a map, and rectangular arenas: read, checked, simulated and drawn. */
class WorldMapTest {

    @TempDir
    Path dir;

    /** A 4 x 3 m room at 0.1 m, walls 0.2 m thick round it, its lower-left corner at (10, -5). */
    private static OccupancyGrid room() {
        int w = 40;
        int h = 30;
        boolean[] blocked = new boolean[w * h];
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                blocked[j * w + i] = i < 2 || j < 2 || i >= w - 2 || j >= h - 2;
            }
        }
        return new OccupancyGrid(w, h, 0.1, 10.0, -5.0, blocked);
    }

    private static String world(String arenaAndMap, double x, double y) {
        return """
                { "name": "mapped", %s,
                  "robot": { "x": %s, "y": %s, "headingDeg": 0 },
                  "obstacles": [ { "shape": "circle", "x": 12.5, "y": -3.0, "radiusM": 0.2 } ],
                  "checkpoints": [ { "x": 13.0, "y": -4.0 } ],
                  "rechargeStation": { "x": 11.0, "y": -3.0, "radiusM": 0.35 } }
                """.formatted(arenaAndMap, x, y);
    }

    @Test
    void aWorldNamingAMapHasItsWallsAsBoxesAfterItsOwnObstaclesAndTheMapsExtentAsArena() throws IOException {
        Path maps = Files.createDirectories(dir.resolve("maps"));
        MapServerWriter.write(room(), maps.resolve("room.yaml"));
        Path file = Files.writeString(dir.resolve("w.json"), world("\"map\": { \"file\": \"maps/room.yaml\" }", 11.0, -4.0));
        WorldSpec w = WorldFiles.load(file); // relative to the world file, not the working directory
        assertThat(w.arena().isCircle()).isFalse();
        assertThat(w.arena().widthM()).isCloseTo(4.0, within(1e-9));
        assertThat(w.arena().heightM()).isCloseTo(3.0, within(1e-9));
        assertThat(w.arena().x()).isCloseTo(12.0, within(1e-9));
        assertThat(w.arena().y()).isCloseTo(-3.5, within(1e-9));
        List<WorldSpec.Obstacle> walls = BoxCover.boxes(room());
        assertThat(walls).hasSize(4);
        assertThat(w.obstacles()).hasSize(5);
        assertThat(w.obstacles().get(0).isCircle()).isTrue();
        assertThat(w.obstacles().subList(1, 5)).isEqualTo(walls);
    }

    @Test
    void aRectangularArenaMayStandBesideAMapOrAlone() throws IOException {
        MapServerWriter.write(room(), dir.resolve("room.yaml"));
        Path file = Files.writeString(dir.resolve("w.json"), world(
                "\"map\": { \"file\": \"room.yaml\" }, \"arena\": { \"widthM\": 6, \"heightM\": 5, \"x\": 12, \"y\": -3.5 }", 11.0, -4.0));
        WorldSpec w = WorldFiles.load(file);
        assertThat(w.arena()).isEqualTo(WorldSpec.Arena.rectangle(6, 5, 12, -3.5));
        WorldSpec alone = WorldFiles.parse("""
                { "name": "alone", "arena": { "widthM": 8, "heightM": 4 }, "robot": { "x": 3.5, "y": 1.5, "headingDeg": 0 },
                  "checkpoints": [ { "x": -3.5, "y": -1.5 } ], "rechargeStation": { "x": 0, "y": 0, "radiusM": 0.35 } }
                """);
        assertThat(alone.arena()).isEqualTo(WorldSpec.Arena.rectangle(8, 4, 0, 0));
        assertThat(alone.arena().inside(3.5, 1.5)).isCloseTo(0.5, within(1e-12));
    }

    private List<String> problems(String json) {
        try {
            WorldFiles.parse(json, "w.json", dir);
            throw new AssertionError("valid: " + json);
        } catch (WorldValidationException e) {
            return e.problems();
        }
    }

    @Test
    void badMapsAndArenasAreNamed() throws IOException {
        assertThat(problems(world("\"map\": { \"file\": \"nope.yaml\" }", 11, -4)))
                .containsExactly("map.file: " + dir.resolve("nope.yaml") + ": no such file");
        MapServerWriter.write(room(), dir.resolve("room.yaml"));
        assertThat(problems(world("\"map\": { \"file\": \"room.yaml\", \"cellM\": 0.5 }", 11, -4)))
                .containsExactly("map.cellM: only a Moving AI map (.map) or a picture alone (.pgm, .png) takes a cell size;"
                        + " a map_server YAML gives its resolution");
        assertThat(problems(world("\"map\": { \"file\": \"room.pgm\" }", 11, -4)))
                .containsExactly("map.cellM: a picture alone has no scale: give cellM (metres a pixel), or name its map_server YAML");
        assertThat(problems(world("\"map\": { \"file\": \"room.yaml\", \"scale\": 2 }", 11, -4)))
                .containsExactly("map.scale: unknown key (expected one of [cellM, file])");
        // the start on the map's left wall
        assertThat(problems(world("\"map\": { \"file\": \"room.yaml\" }", 10.25, -4)))
                .containsExactly("robot: start (10.25, -4.00) is on a wall of the map " + dir.resolve("room.yaml")
                        + " (occupied or unknown cells): the robot (radius 0.12 m) would overlap it");
        assertThat(problems(world("\"arena\": { \"radiusM\": 5, \"widthM\": 3, \"heightM\": 3 }", 0, 0)))
                .containsExactly("arena: give radiusM (a circle) or widthM and heightM (a rectangle), not both");
        assertThat(problems(world("\"arena\": { \"radiusM\": 20, \"x\": 1 }", 11, -4)))
                .containsExactly("arena.x: only a rectangle has a centre; a circular arena is centred on (0, 0)");
        assertThat(problems(world("\"arena\": { \"widthM\": 3 }", 0, 0))).contains("arena.heightM: missing required key");
        assertThat(problems(world("\"arena\": { \"widthM\": 2, \"heightM\": 2 }", 0.95, 0)).get(0))
                .isEqualTo("robot: start (0.95, 0.00) is outside the arena: the robot's centre (radius 0.12 m) stays within"
                        + " x -0.88 to 0.88 and y -0.88 to 0.88");
        // without a map the arena stays required
        assertThat(problems(world("\"seed\": 1", 0, 0))).contains("arena: missing required key");
    }

    @Test
    void theRectanglesWallStopsTheRobotAndCountsAsACollision() {
        WorldSpec w = new WorldSpec("rect", 32, 600, 1, WorldSpec.Arena.rectangle(3.0, 2.0, 1.0, 0.5),
                new WorldSpec.Robot(1.0, 0.5, 0.0, 0.12, 0.5, 1.0), List.of(), List.of(new WorldSpec.Checkpoint(0, 0)), 0.25,
                new WorldSpec.RechargeStation(0, 0, 0.35), WorldSpec.Battery.DEFAULT);
        Simulation sim = new Simulation(w);
        assertThat(sim.groundTruth().minClearanceM()).isCloseTo(1.0 - 0.12, within(1e-9)); // 1 m to the top and bottom sides
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 200); // 3.2 m without the wall at x = 2.5
        GroundTruth t = sim.groundTruth();
        assertThat(t.collisions()).isEqualTo(1);
        assertThat(t.x()).isCloseTo(2.5 - 0.12, within(0.01));
        assertThat(t.minClearanceM()).isZero();
        String svg = new SvgRenderer(w).render();
        assertThat(svg).contains("viewBox=\"-1.300 -2.300 4.600 3.600\"").contains("<g id=\"arena\"><rect ");
    }
}
