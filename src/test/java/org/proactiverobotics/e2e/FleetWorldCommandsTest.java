package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonParser;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.proactiverobotics.app.generate.Solvability;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Worlds with several robots through the real command line (issue 34, docs/world-file.md "Several robots"): {@code validate} and
 * {@code run} refuse a bad fleet with its key path, exit 2, nothing written; {@code generate --robots N} draws
 * valid worlds whose every mission is solvable, the same for the same seed, and one robot as before.
 */
class FleetWorldCommandsTest extends CommandLineTest {

    @TempDir
    Path tmp;

    /** The project's examples/fleet/ directory, found from wherever the tests run. */
    private static Path fleetExamples() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("examples/fleet"))) {
                return p.resolve("examples/fleet");
            }
        }
        throw new IllegalStateException("no examples/fleet/ above " + Path.of("").toAbsolutePath());
    }

    @Test
    void validateListsEveryRobotOfTheExampleFleets() {
        assertThat(run("validate", "--world", fleetExamples().resolve("fleet-corridor.json").toString())).as(err.toString())
                .isZero();
        assertThat(out.toString().lines().toList()).containsExactly(
                "fleet-corridor: valid (2 robots, 2 obstacles, 2 checkpoints, 2 recharge stations, arena 8.0 x 3.0 m centred on (0.0, 0.0))",
                "  robot 1: start (-3.0, 0.0) heading 0.0°, radius 0.15 m, 1 checkpoint (3.0, 0.0)",
                "  robot 2: start (3.0, 0.0) heading 180.0°, radius 0.15 m, 1 checkpoint (-3.0, 0.0)");
        assertThat(run("validate", "--world", fleetExamples().resolve("fleet-station.json").toString())).isZero();
        assertThat(out.toString()).contains("fleet-station: valid (6 robots, 0 obstacles, 6 checkpoints, 1 recharge station");
    }

    @Test
    void everyExampleFleetMissionIsSolvableAndTheStationWorldNeedsItsOneStation() throws Exception {
        for (String name : List.of("fleet-corridor", "fleet-station")) {
            WorldSpec world = WorldFiles.load(fleetExamples().resolve(name + ".json"));
            assertThat(Solvability.ofEachRobot(world)).as(name).allMatch(Solvability::solvable);
        }
        // every robot of fleet-station must charge on the way: six at one station at once
        WorldSpec station = WorldFiles.load(fleetExamples().resolve("fleet-station.json"));
        assertThat(station.robots()).hasSize(6);
        assertThat(Solvability.ofEachRobot(station)).allMatch(plan -> plan.recharges() == 1);
        // fleet-corridor's corridor is 0.6 m wide: its two 0.3 m robots cannot pass each other inside it
        WorldSpec corridor = WorldFiles.load(fleetExamples().resolve("fleet-corridor.json"));
        assertThat(corridor.robots()).allMatch(r -> r.robot().radiusM() * 4 >= 0.6);
    }

    @Test
    void theManualsFleetExampleIsTheExampleFile() throws Exception {
        String manual = Files.readString(fleetExamples().resolve("../../docs/world-file.md").normalize());
        int at = manual.indexOf("```json\n{\n  \"name\": \"fleet-corridor\"");
        assertThat(at).as("docs/world-file.md shows fleet-corridor.json").isPositive();
        String block = manual.substring(at + 8, manual.indexOf("```", at + 8));
        assertThat(JsonParser.parseString(block))
                .isEqualTo(JsonParser.parseString(Files.readString(fleetExamples().resolve("fleet-corridor.json"))));
    }

    /** A bad fleet, the key path of its one problem. */
    private static final Map<String, String> BAD_FLEETS = Map.of(
            "duplicate-ids", "robots[1].id: 1 is robots[0]'s id too",
            "inside-another", "robots[1]: start (-2.90, 0.00) is inside robots[0]",
            "with-robot", "robot: a world with \"robots\" describes each robot there",
            "with-checkpoints", "checkpoints: a world with \"robots\" gives each robot its checkpoints",
            "both-station-keys", "rechargeStation: give rechargeStation (one) or rechargeStations (several), not both",
            "empty", "robots: must list at least one robot",
            "checkpoint-in-obstacle", "robots[1].checkpoints[0]: checkpoint (0.00, 0.90) is inside obstacle obstacles[0]");

    private Path badFleet(String kind) throws Exception {
        String json = Files.readString(fleetExamples().resolve("fleet-corridor.json"), StandardCharsets.UTF_8);
        String robot2 = "{ \"id\": 2, \"x\": 3.0, \"y\": 0.0,";
        String bad = switch (kind) {
            case "duplicate-ids" -> json.replace("\"id\": 2,", "\"id\": 1,");
            case "inside-another" -> json.replace(robot2, "{ \"id\": 2, \"x\": -2.9, \"y\": 0.0,");
            case "with-robot" -> json.replace("\"robots\":", "\"robot\": { \"x\": 0, \"y\": 0, \"headingDeg\": 0 }, \"robots\":");
            case "with-checkpoints" -> json.replace("\"robots\":", "\"checkpoints\": [ { \"x\": 1, \"y\": 0 } ], \"robots\":");
            case "both-station-keys" -> json.replace("\"rechargeStations\":",
                    "\"rechargeStation\": { \"x\": -3.3, \"y\": -1.0, \"radiusM\": 0.35 }, \"rechargeStations\":");
            case "empty" -> json.substring(0, json.indexOf("\"robots\": [") + 11) + "]" + json.substring(json.indexOf("  ],\n  \"obstacles\"") + 3);
            case "checkpoint-in-obstacle" -> json.replace("\"checkpoints\": [ { \"x\": -3.0, \"y\": 0.0 } ]",
                    "\"checkpoints\": [ { \"x\": 0.0, \"y\": 0.9 } ]");
            default -> throw new IllegalArgumentException(kind);
        };
        assertThat(bad).isNotEqualTo(json);
        Path file = tmp.resolve(kind + ".json");
        Files.writeString(file, bad);
        return file;
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"duplicate-ids", "inside-another", "with-robot", "with-checkpoints", "both-station-keys", "empty",
            "checkpoint-in-obstacle"})
    void aBadFleetIsOneLineNamingItsKeyPathExitTwoAndNothingWritten(String kind) throws Exception {
        Path file = badFleet(kind);
        assertThat(run("validate", "--world", file.toString())).isEqualTo(2);
        assertThat(out.toString()).isEmpty();
        List<String> lines = err.toString().lines().toList();
        assertThat(lines).hasSize(1);
        assertThat(lines.get(0)).startsWith(file + ": invalid world file: " + BAD_FLEETS.get(kind));

        Path runOut = tmp.resolve("run-" + kind);
        assertThat(run("run", "--world", file.toString(), "--quiet", "--out", runOut.toString())).isEqualTo(2);
        assertThat(runOut).doesNotExist();
        assertThat(out.toString()).isEmpty();
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"cluttered", "traps", "corridors", "battery", "pillars", "rooms", "maze"})
    void generateFourRobotsGivesValidWorldsWhoseMissionsAreSolvableAndCross(String kind) throws Exception {
        Path a = tmp.resolve("a");
        Path b = tmp.resolve("b");
        assertThat(run("generate", "--kind", kind, "--count", "2", "--seed", "5", "--robots", "4", "--out", a.toString()))
                .as(err.toString()).isZero();
        assertThat(run("generate", "--kind", kind, "--count", "2", "--seed", "5", "--robots", "4", "--out", b.toString()))
                .as(err.toString()).isZero();
        assertThat(out.toString()).contains("4 robots", "2 stations", "longest planned path");
        for (String name : List.of(kind + "-001.json", kind + "-002.json")) {
            Path file = a.resolve(name);
            assertThat(Files.readString(file)).as("the same seed, the same world").isEqualTo(Files.readString(b.resolve(name)));
            WorldSpec world = WorldFiles.load(file); // valid, or this throws naming its problems
            assertThat(world.robots()).extracting(WorldSpec.RobotEntry::id).containsExactly(1, 2, 3, 4);
            assertThat(world.rechargeStations()).hasSize(2);
            assertThat(Solvability.ofEachRobot(world)).as(name).allSatisfy(plan -> assertThat(plan.solvable())
                    .as(name + ": " + plan.reason()).isTrue());
            double r = world.robot().radiusM();
            // a robot that backs out for another must see behind it: every fleet robot has rays at 150°, 180° and -150°
            assertThat(world.robots()).allSatisfy(e -> assertThat(e.robot().sensorAnglesDeg())
                    .startsWith(-150.0).endsWith(150.0, 180.0)
                    .containsSubsequence(WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.toArray(Double[]::new)));
            for (int i = 0; i < 4; i++) {
                WorldSpec.RobotEntry me = world.robots().get(i);
                for (int j = 0; j < 4; j++) {
                    WorldSpec.RobotEntry other = world.robots().get(j);
                    if (i == j) {
                        continue;
                    }
                    // starts a body's width apart (rim to rim), and off each other's checkpoints
                    assertThat(distance(me.robot(), other.robot().x(), other.robot().y())).isGreaterThanOrEqualTo(4 * r);
                    for (WorldSpec.Checkpoint c : other.checkpoints()) {
                        assertThat(distance(me.robot(), c.x(), c.y())).isGreaterThan(world.checkpointRadiusM() + r);
                    }
                }
                if (i > 0) {
                    // crossing: robot k's first checkpoint lies nearer another robot's start than its own
                    WorldSpec.Checkpoint c = me.checkpoints().get(0);
                    double own = distance(me.robot(), c.x(), c.y());
                    assertThat(world.robots().stream().filter(o -> o != me).mapToDouble(o -> distance(o.robot(), c.x(), c.y())).min()
                            .orElseThrow()).as(name + " robot " + me.id()).isLessThan(own);
                }
            }
            assertThat(run("validate", "--world", file.toString())).isZero();
        }
    }

    private static double distance(WorldSpec.Robot robot, double x, double y) {
        return Math.hypot(robot.x() - x, robot.y() - y);
    }

    /**
     * A strategy file may rank the traffic scenario, Yield, for a world with several robots (where the engine runs it);
     * for a one-robot world, which has no Yield, the same file is refused naming it, exit 2, nothing written.
     */
    @Test
    void aStrategyFileMayRankYieldForAWorldWithSeveralRobotsOnly() throws Exception {
        Path strategy = Files.writeString(tmp.resolve("yield-low.json"), "{\"name\": \"yield-low\", \"priorities\":"
                + " {\"ObstacleAvoidance\": 9, \"BatteryMonitor\": 5, \"Yield\": 4, \"ReachDestination\": 1}}");
        Path fleet = Files.writeString(tmp.resolve("three-hops.json"), FleetTwoProcessTest.THREE_HOPS);
        Path out = tmp.resolve("fleet-out");
        assertThat(run("run", "--world", fleet.toString(), "--link", "direct", "--strategy-file", strategy.toString(),
                "--quiet", "--out", out.toString())).as(err.toString()).isZero();
        assertThat(out.toString()).isNotEmpty();
        assertThat(err.toString()).doesNotContain("leaves out");
        assertThat(JsonParser.parseString(Files.readString(out.resolve("report.json"))).getAsJsonObject().get("strategy")
                .getAsString()).isEqualTo("yield-low");

        Path one = Files.writeString(tmp.resolve("one.json"), "{\"name\": \"one\", \"arena\": {\"radiusM\": 2.0},"
                + " \"robot\": {\"x\": 0, \"y\": 0, \"headingDeg\": 0}, \"checkpoints\": [{\"x\": 1, \"y\": 0}],"
                + " \"rechargeStation\": {\"x\": -1, \"y\": 0, \"radiusM\": 0.3}}");
        Path oneOut = tmp.resolve("one-out");
        assertThat(run("run", "--world", one.toString(), "--link", "direct", "--strategy-file", strategy.toString(),
                "--quiet", "--out", oneOut.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("yield-low.json: strategy yield-low names scenario 'Yield', which is not loaded");
        assertThat(oneOut).doesNotExist();
    }

    @Test
    void generateRobotsOutOfRangeIsBadInputAndWritesNothing() {
        Path out = tmp.resolve("out");
        assertThat(run("generate", "--kind", "rooms", "--count", "1", "--robots", "0", "--out", out.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--robots must be from 1 to 8: 0");
        assertThat(run("generate", "--kind", "rooms", "--count", "1", "--robots", "9", "--out", out.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--robots must be from 1 to 8: 9");
        assertThat(out).doesNotExist();
    }

    /**
     * One robot (the default and {@code --robots 1}) draws what {@code generate} drew before fleets, byte for byte:
     * the SHA-256 of each kind's first world for seed 7, taken from main's jar before {@code --robots} existed.
     */
    @Test
    void oneRobotWorldsAreTheSameAsBeforeFleetsByteForByte() throws Exception {
        Map<String, String> before = Map.of(
                "cluttered", "599daeff0f6f8c53b2ad89310467953df0333ec433f7d6d496f29e01a6f57cbd",
                "traps", "d3781098d43c14964f9776fd81b623203c8c41dd9790b174f9ab7a1fb1cba59d",
                "corridors", "182dac18990c52cf042e83ad297a30c2c8a9c1b925a723faa0779c7ccea34bab",
                "battery", "fdd0d25eeed87ce25b27c5b45bdc97a60ab58428d990300f1e8b4586eec198f4",
                "pillars", "12e9570745e3e633e9c4e99f68b67861e3e279941be44d3903ae2010a169051f",
                "rooms", "c1934f932ba9ac08e335cb593e054838745bbc15f3fe66d6f42a315d2a3319a9",
                "maze", "9715d636dbb35406a6370d850ec399258873a20861ab6318748a0c50efc6b1a2");
        for (Map.Entry<String, String> kind : before.entrySet()) {
            Path dflt = tmp.resolve("default-" + kind.getKey());
            Path one = tmp.resolve("one-" + kind.getKey());
            assertThat(run("generate", "--kind", kind.getKey(), "--count", "1", "--seed", "7", "--out", dflt.toString())).isZero();
            assertThat(run("generate", "--kind", kind.getKey(), "--count", "1", "--seed", "7", "--robots", "1", "--out",
                    one.toString())).isZero();
            for (Path dir : List.of(dflt, one)) {
                byte[] file = Files.readAllBytes(dir.resolve(kind.getKey() + "-001.json"));
                assertThat(HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(file))).as(kind.getKey())
                        .isEqualTo(kind.getValue());
            }
            try (Stream<Path> s = Files.list(dflt)) {
                assertThat(s.count()).isOne();
            }
        }
    }
}
