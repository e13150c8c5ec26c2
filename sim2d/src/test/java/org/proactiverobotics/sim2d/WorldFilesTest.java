package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class WorldFilesTest {

    /** A complete world file: every section present. */
    static final String COMPLETE_EXAMPLE = """
            {
              "name": "reference-arena",
              "timeStepMs": 32,
              "maxSimTimeS": 600,
              "seed": 1,
              "arena": { "radiusM": 5.0 },
              "robot": { "x": 0.0, "y": -4.0, "headingDeg": 90.0 },
              "obstacles": [
                { "shape": "box", "x": 0.0, "y": -1.5, "widthM": 2.0, "heightM": 0.4, "angleDeg": 0.0 },
                { "shape": "circle", "x": 2.0, "y": 1.0, "radiusM": 0.5 }
              ],
              "checkpoints": [ { "x": 0.0, "y": 3.0 }, { "x": 3.0, "y": -1.0 } ],
              "checkpointRadiusM": 0.25,
              "rechargeStation": { "x": -3.0, "y": 0.0, "radiusM": 0.35 },
              "battery": { "initial": 100.0, "drainPerMeter": 1.0, "rechargeTo": 100.0, "rechargeRatePerS": 10.0 }
            }
            """;

    /** Only the required keys. */
    static final String MINIMAL = """
            { "name": "m", "arena": { "radiusM": 5 }, "robot": { "x": 0, "y": 0, "headingDeg": 0 },
              "checkpoints": [ { "x": 1, "y": 1 } ], "rechargeStation": { "x": -1, "y": 0, "radiusM": 0.3 } }
            """;

    private static List<String> problems(String json) {
        return catchThrowableOfType(WorldValidationException.class, () -> WorldFiles.parse(json)).problems();
    }

    /** The minimal file with one key's text replaced. */
    private static String minimalWith(String from, String to) {
        assertThat(MINIMAL).contains(from);
        return MINIMAL.replace(from, to);
    }

    @Test
    void parsesTheDesignExample() {
        WorldSpec w = WorldFiles.parse(COMPLETE_EXAMPLE);
        assertThat(w.name()).isEqualTo("reference-arena");
        assertThat(w.timeStepMs()).isEqualTo(32);
        assertThat(w.seed()).isEqualTo(1);
        assertThat(w.arena().radiusM()).isEqualTo(5.0);
        assertThat(w.robot().headingDeg()).isEqualTo(90.0);
        assertThat(w.obstacles()).containsExactly(WorldSpec.Obstacle.box(0.0, -1.5, 2.0, 0.4, 0.0),
                WorldSpec.Obstacle.circle(2.0, 1.0, 0.5));
        assertThat(w.checkpoints()).containsExactly(new WorldSpec.Checkpoint(0, 3), new WorldSpec.Checkpoint(3, -1));
        assertThat(w.rechargeStation()).isEqualTo(new WorldSpec.RechargeStation(-3, 0, 0.35));
        assertThat(w.battery()).isEqualTo(WorldSpec.Battery.DEFAULT);
    }

    @Test
    void appliesDefaults() {
        WorldSpec w = WorldFiles.parse(MINIMAL);
        assertThat(w.timeStepMs()).isEqualTo(32);
        assertThat(w.maxSimTimeS()).isEqualTo(600.0);
        assertThat(w.seed()).isZero();
        assertThat(w.obstacles()).isEmpty();
        assertThat(w.checkpointRadiusM()).isEqualTo(0.25);
        assertThat(w.battery()).isEqualTo(new WorldSpec.Battery(100, 1.0, 100, 10));
        assertThat(w.robot()).isEqualTo(new WorldSpec.Robot(0, 0, 0, 0.12, 0.5, 1.0));
    }

    @Test
    void appliesDefaultsInsideObjects() {
        WorldSpec w = WorldFiles.parse(MINIMAL.replace("\"checkpoints\"",
                "\"battery\": { \"initial\": 40 }, \"obstacles\": [ { \"shape\": \"box\", \"x\": 3, \"y\": 3, \"widthM\": 1, \"heightM\": 1 } ], \"checkpoints\""));
        assertThat(w.battery()).isEqualTo(new WorldSpec.Battery(40, 1.0, 100, 10));
        assertThat(w.obstacles().get(0).angleDeg()).isZero();
    }

    // ---- one test per rule ----

    @Test
    void brokenJson() {
        assertThat(problems("{ \"name\": \"x\", ")).singleElement().asString().startsWith("(root): malformed JSON");
        assertThat(problems("")).singleElement().asString().startsWith("(root): malformed JSON");
        assertThat(problems(MINIMAL + " {}")).singleElement().asString().startsWith("(root): malformed JSON");
        assertThat(problems("// comment\n" + MINIMAL)).singleElement().asString().startsWith("(root): malformed JSON");
        assertThat(problems("[1, 2]")).containsExactly("(root): expected a JSON object, got an array");
    }

    @Test
    void aJsonSyntaxErrorSaysInOurWordsWhatAndWhereWithoutTheParsersAdviceOrLink() {
        assertThat(problems("{\"name\": \"x\", \"arena\": {\"radiusM\": 3}\n  \"robot\": 1}")).containsExactly(
                "(root): malformed JSON: an object is not closed, or a ',' is missing between its entries (line 2, column 4, in arena)");
        assertThat(problems("{\"name\": x}")).singleElement().asString()
                .startsWith("(root): malformed JSON: not strict JSON").contains("(line 1, column 10, in name)");
        assertThat(problems("{\"name\": \"x\",\n \"timeStepMs\": \"32,\n \"arena\": {}}")).singleElement().asString()
                .startsWith("(root): malformed JSON: a string runs over a line end or holds a tab (a closing '\"' missing?)")
                .contains("line 2");
        for (String broken : List.of("{\"name\": \"x\",}", "{\"a\": [1,]}", "{\"a\" 1}", "{\"a\": \"b", "// c\n{}", "{'a': 1}",
                "{\"a\": \"\\q\"}", "{\"a\": 1", MINIMAL + " {}")) {
            assertThat(problems(broken)).as(broken).singleElement().asString().startsWith("(root): malformed JSON: ")
                    .doesNotContain("setStrictness").doesNotContain("LENIENT").doesNotContain("http").doesNotContain("\n")
                    .doesNotContain("$");
        }
    }

    @Test
    void unknownKeys() {
        assertThat(problems(minimalWith("\"name\": \"m\"", "\"name\": \"m\", \"gravity\": 9.8")))
                .singleElement().asString().startsWith("gravity: unknown key");
        assertThat(problems(minimalWith("\"headingDeg\": 0", "\"headingDeg\": 0, \"speed\": 1")))
                .singleElement().asString().startsWith("robot.speed: unknown key");
        assertThat(problems(minimalWith("{ \"x\": 1, \"y\": 1 }", "{ \"x\": 1, \"y\": 1, \"z\": 0 }")))
                .singleElement().asString().startsWith("checkpoints[0].z: unknown key");
    }

    @Test
    void keysOfTheOtherShapeAreUnknown() {
        String json = MINIMAL.replace("\"checkpoints\"",
                "\"obstacles\": [ { \"shape\": \"circle\", \"x\": 3, \"y\": 3, \"radiusM\": 0.5, \"widthM\": 1 } ], \"checkpoints\"");
        assertThat(problems(json)).singleElement().asString().startsWith("obstacles[0].widthM: unknown key");
    }

    @Test
    void missingRequiredKeys() {
        assertThat(problems("{}")).containsExactly(
                "name: missing required key",
                "arena: missing required key",
                "robot: missing required key",
                "checkpoints: missing required key",
                "rechargeStation: missing required key");
        assertThat(problems(minimalWith("\"x\": 0, \"y\": 0, ", "")))
                .containsExactly("robot.x: missing required key", "robot.y: missing required key");
        assertThat(problems(minimalWith("\"radiusM\": 5", ""))).containsExactly("arena.radiusM: missing required key");
    }

    @Test
    void missingKeysOfAnObstacle() {
        String json = MINIMAL.replace("\"checkpoints\"",
                "\"obstacles\": [ { \"x\": 3, \"y\": 3 }, { \"shape\": \"box\", \"x\": 3, \"y\": 3, \"widthM\": 1 } ], \"checkpoints\"");
        assertThat(problems(json)).containsExactly("obstacles[0].shape: missing required key",
                "obstacles[1].heightM: missing required key");
    }

    @Test
    void atLeastOneCheckpoint() {
        assertThat(problems(minimalWith("[ { \"x\": 1, \"y\": 1 } ]", "[]")))
                .containsExactly("checkpoints: must list at least one checkpoint");
    }

    @Test
    void wrongTypes() {
        assertThat(problems(minimalWith("\"name\": \"m\"", "\"name\": 3")))
                .containsExactly("name: expected a string, got a number (3)");
        assertThat(problems(minimalWith("\"x\": 1, \"y\": 1", "\"x\": \"one\", \"y\": 1")))
                .containsExactly("checkpoints[0].x: expected a number, got a string (\"one\")");
        assertThat(problems(minimalWith("\"radiusM\": 5", "\"radiusM\": null")))
                .containsExactly("arena.radiusM: expected a number, got null");
        assertThat(problems(minimalWith("\"arena\": { \"radiusM\": 5 }", "\"arena\": 5")))
                .containsExactly("arena: expected an object, got a number (5)");
        assertThat(problems(minimalWith("\"checkpoints\": [ { \"x\": 1, \"y\": 1 } ]", "\"checkpoints\": { }")))
                .containsExactly("checkpoints: expected an array, got an object");
        assertThat(problems(minimalWith("[ { \"x\": 1, \"y\": 1 } ]", "[ true ]")))
                .containsExactly("checkpoints[0]: expected an object, got a boolean (true)");
        assertThat(problems(minimalWith("\"name\": \"m\"", "\"name\": \"m\", \"timeStepMs\": 2.5")))
                .containsExactly("timeStepMs: must be an integer from 1 to 1000, got 2.50");
        assertThat(problems(minimalWith("\"name\": \"m\"", "\"name\": \"m\", \"seed\": 1.5")))
                .singleElement().asString().startsWith("seed: must be an integer");
    }

    @Test
    void nonFiniteNumbers() {
        assertThat(problems(minimalWith("\"headingDeg\": 0", "\"headingDeg\": 1e999")))
                .containsExactly("robot.headingDeg: must be a finite number, got 1e999");
        assertThat(problems(minimalWith("\"x\": 1, \"y\": 1", "\"x\": 1, \"y\": -1e400")))
                .containsExactly("checkpoints[0].y: must be a finite number, got -1e400");
    }

    @Test
    void sizesMustBePositive() {
        assertThat(problems(minimalWith("\"radiusM\": 5", "\"radiusM\": 0")))
                .containsExactly("arena.radiusM: must be > 0, got 0");
        assertThat(problems(minimalWith("\"headingDeg\": 0", "\"headingDeg\": 0, \"sensorRangeM\": -1, \"radiusM\": 0")))
                .containsExactly("robot.radiusM: must be > 0, got 0", "robot.sensorRangeM: must be > 0, got -1");
        assertThat(problems(minimalWith("\"radiusM\": 0.3", "\"radiusM\": -0.3")))
                .containsExactly("rechargeStation.radiusM: must be > 0, got -0.3");
        String json = MINIMAL.replace("\"checkpoints\"",
                "\"checkpointRadiusM\": 0, \"obstacles\": [ { \"shape\": \"box\", \"x\": 3, \"y\": 3, \"widthM\": 0, \"heightM\": 1 } ], \"checkpoints\"");
        assertThat(problems(json)).containsExactly("obstacles[0].widthM: must be > 0, got 0",
                "checkpointRadiusM: must be > 0, got 0");
    }

    @Test
    void rangesOfOtherNumbers() {
        assertThat(problems(minimalWith("\"name\": \"m\"", "\"name\": \"m\", \"timeStepMs\": 0")))
                .containsExactly("timeStepMs: must be an integer from 1 to 1000, got 0.00");
        assertThat(problems(minimalWith("\"name\": \"m\"", "\"name\": \"m\", \"timeStepMs\": 1001")))
                .containsExactly("timeStepMs: must be an integer from 1 to 1000, got 1001.00");
        assertThat(problems(minimalWith("\"name\": \"m\"",
                "\"name\": \"m\", \"battery\": { \"initial\": 120, \"drainPerMeter\": -1, \"rechargeRatePerS\": 0 }")))
                .containsExactly("battery.initial: must be > 0 and <= 100, got 120",
                        "battery.drainPerMeter: must be >= 0, got -1", "battery.rechargeRatePerS: must be > 0, got 0");
        assertThat(problems(minimalWith("\"name\": \"m\"", "\"name\": \"m b\"")))
                .singleElement().asString().startsWith("name: must be letters, digits");
    }

    @Test
    void unknownObstacleShape() {
        String json = MINIMAL.replace("\"checkpoints\"",
                "\"obstacles\": [ { \"shape\": \"triangle\", \"x\": 3, \"y\": 3 } ], \"checkpoints\"");
        assertThat(problems(json)).containsExactly("obstacles[0].shape: unknown shape \"triangle\" (expected \"box\" or \"circle\")");
    }

    @Test
    void startOutsideTheArena() {
        assertThat(problems(minimalWith("\"x\": 0, \"y\": 0, \"headingDeg\"", "\"x\": 4.95, \"y\": 0, \"headingDeg\"")))
                .singleElement().asString().startsWith("robot: start (4.95, 0.00) is outside the arena");
    }

    @Test
    void checkpointOrStationOutsideTheArena() {
        assertThat(problems(minimalWith("\"x\": 1, \"y\": 1", "\"x\": 6, \"y\": 1")))
                .singleElement().asString().startsWith("checkpoints[0]: checkpoint (6.00, 1.00) is outside the arena");
        assertThat(problems(minimalWith("\"x\": -1, \"y\": 0", "\"x\": -1, \"y\": -9")))
                .singleElement().asString().startsWith("rechargeStation: station (-1.00, -9.00) is outside the arena");
    }

    @Test
    void startCheckpointOrStationInsideAnObstacle() {
        String json = MINIMAL.replace("\"checkpoints\"", """
                "obstacles": [ { "shape": "circle", "x": 4, "y": 4, "radiusM": 0.3 },
                               { "shape": "box", "x": 0.5, "y": 0.5, "widthM": 3, "heightM": 0.4, "angleDeg": 45 },
                               { "shape": "circle", "x": -1.1, "y": 0, "radiusM": 0.05 } ], "checkpoints\"""");
        assertThat(problems(json)).containsExactly(
                "robot: start (0.00, 0.00) is inside obstacle obstacles[1]: the robot (radius 0.12 m) would overlap it",
                "checkpoints[0]: checkpoint (1.00, 1.00) is inside obstacle obstacles[1]: the robot (radius 0.12 m) would overlap it",
                "rechargeStation: station (-1.00, 0.00) is inside obstacle obstacles[2]: the robot (radius 0.12 m) would overlap it");
    }

    @Test
    void aFileWithSeveralProblemsReportsThemAll() {
        String json = """
                { "name": "bad name", "timeStepMs": 0, "colour": "red",
                  "arena": { "radiusM": -5 },
                  "robot": { "x": "0", "y": 0, "headingDeg": 90, "sensorRangeM": 0 },
                  "obstacles": [ { "shape": "hexagon", "x": 0, "y": 0 }, { "shape": "circle", "x": 1, "y": 1 } ],
                  "checkpoints": [ { "x": 1, "y": 1 }, { "x": 1 }, { "x": 1, "y": 1e999 } ],
                  "rechargeStation": { "x": 0, "y": 0 },
                  "battery": { "initial": 0, "rechargeTo": 100 } }
                """;
        WorldValidationException e = catchThrowableOfType(WorldValidationException.class, () -> WorldFiles.parse(json));
        assertThat(e.problems()).extracting(p -> p.substring(0, p.indexOf(':'))).containsExactly(
                "colour", "name", "timeStepMs", "arena.radiusM", "robot.x", "robot.sensorRangeM",
                "obstacles[0].shape", "obstacles[1].radiusM", "checkpoints[1].y", "checkpoints[2].y",
                "rechargeStation.radiusM", "battery.initial");
        assertThat(e.getMessage()).contains("12 problems").contains("checkpoints[2].y: must be a finite number");
    }

    @Test
    void unreadableFile(@TempDir Path dir) {
        assertThatThrownBy(() -> WorldFiles.load(dir.resolve("missing.json")))
                .isInstanceOf(WorldValidationException.class)
                .satisfies(e -> assertThat(((WorldValidationException) e).problems())
                        .singleElement().asString().contains("no such file"));
    }

    @Test
    void loadsFromDisk(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("w.json");
        Files.writeString(file, COMPLETE_EXAMPLE);
        assertThat(WorldFiles.load(file)).isEqualTo(WorldFiles.parse(COMPLETE_EXAMPLE));
    }

    // ---- bundled worlds ----

    static List<String> bundledNames() {
        return WorldFiles.bundledNames();
    }

    @Test
    void bundlesTheExampleWorlds() {
        assertThat(WorldFiles.bundledNames()).contains("reference-arena", "obstacle-across-path", "cluttered-arena",
                "low-battery");
        assertThat(WorldFiles.defaultWorld().name()).isEqualTo(WorldFiles.DEFAULT_WORLD);
        assertThat(WorldFiles.bundled("low-battery.json").name()).isEqualTo("low-battery");
        assertThatThrownBy(() -> WorldFiles.bundled("nowhere")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("reference-arena");
    }

    @ParameterizedTest
    @MethodSource("bundledNames")
    void everyBundledWorldValidatesAndIsNamedAfterItsFile(String name) {
        WorldSpec w = WorldFiles.bundled(name);
        assertThat(w.name()).isEqualTo(name);
    }

    @ParameterizedTest
    @MethodSource("bundledNames")
    void everyBundledWorldSaysWhatItIsFor(String name) {
        assertThat(WorldFiles.description(name)).as(name + " in worlds/descriptions.properties").isNotBlank();
    }

    @ParameterizedTest
    @MethodSource("bundledNames")
    void everyBundledWorldLeavesRoomToManoeuvre(String name) {
        WorldSpec w = WorldFiles.bundled(name);
        double r = w.arena().radiusM();
        List<double[]> points = new java.util.ArrayList<>();
        points.add(new double[] {w.robot().x(), w.robot().y()});
        w.checkpoints().forEach(c -> points.add(new double[] {c.x(), c.y()}));
        points.add(new double[] {w.rechargeStation().x(), w.rechargeStation().y()});
        for (double[] p : points) {
            assertThat(Math.hypot(p[0], p[1])).as("distance from centre").isLessThanOrEqualTo(r - 0.6);
            for (WorldSpec.Obstacle o : w.obstacles()) {
                assertThat(o.distanceTo(p[0], p[1])).as("clearance of (%s, %s) to %s", p[0], p[1], o).isGreaterThanOrEqualTo(0.4);
            }
        }
    }
}
