package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** World files with several robots (docs/world-file.md, "Several robots"). */
class FleetWorldFilesTest {

    /** The manual's fleet example, with the rest of a world round it. */
    static final String FLEET = """
            { "name": "two", "arena": { "radiusM": 5 },
              "robots": [
                { "id": 1, "x": -3.0, "y": 0.0, "headingDeg": 0, "checkpoints": [ { "x": 3.0, "y": 0.0 } ] },
                { "id": 2, "x": 3.0, "y": 0.5, "headingDeg": 180, "radiusM": 0.15,
                  "checkpoints": [ { "x": -3.0, "y": 0.5 }, { "x": 0.0, "y": 3.0 } ] }
              ],
              "obstacles": [ { "shape": "circle", "x": 0, "y": -2, "radiusM": 0.5 } ],
              "rechargeStations": [ { "x": -1, "y": -4, "radiusM": 0.3 }, { "x": 1, "y": -4, "radiusM": 0.3 } ] }
            """;

    private static List<String> problems(String json) {
        WorldValidationException e = catchThrowableOfType(WorldValidationException.class, () -> WorldFiles.parse(json));
        assertThat(e).as("expected the world to be invalid").isNotNull();
        return e.problems();
    }

    private static String fleetWith(String from, String to) {
        assertThat(FLEET).contains(from);
        return FLEET.replace(from, to);
    }

    @Test
    void readsEachRobotWithItsOwnPropertiesAndCheckpointsAndEveryStation() {
        WorldSpec w = WorldFiles.parse(FLEET);
        assertThat(w.hasSeveralRobots()).isTrue();
        assertThat(w.robots()).extracting(WorldSpec.RobotEntry::id).containsExactly(1, 2);
        WorldSpec.RobotEntry second = w.robots().get(1);
        assertThat(second.robot()).isEqualTo(new WorldSpec.Robot(3.0, 0.5, 180, 0.15, 0.5, 1.0));
        assertThat(second.checkpoints()).containsExactly(new WorldSpec.Checkpoint(-3.0, 0.5), new WorldSpec.Checkpoint(0.0, 3.0));
        // robot() and checkpoints() are the first robot's, rechargeStation() the first station
        assertThat(w.robot()).isEqualTo(new WorldSpec.Robot(-3.0, 0.0, 0, 0.12, 0.5, 1.0));
        assertThat(w.checkpoints()).containsExactly(new WorldSpec.Checkpoint(3.0, 0.0));
        assertThat(w.rechargeStations()).containsExactly(new WorldSpec.RechargeStation(-1, -4, 0.3),
                new WorldSpec.RechargeStation(1, -4, 0.3));
        assertThat(w.rechargeStation()).isEqualTo(w.rechargeStations().get(0));
    }

    /* Every robot's mission charged at the first station, though the generator checked each mission against the station
       nearest its start: robots crossed the floor to charge (issue 34's generated corridors worlds). */
    @Test
    void eachRobotsMissionChargesAtTheStationNearestItsStart() {
        WorldSpec w = WorldFiles.parse(FLEET);
        WorldSpec first = w.forRobot(0);  // starts at (-3, 0): (-1, -4) is nearer than (1, -4)
        WorldSpec second = w.forRobot(1); // starts at (3, 0.5): (1, -4) is nearer
        assertThat(first.rechargeStation()).isEqualTo(new WorldSpec.RechargeStation(-1, -4, 0.3));
        assertThat(second.rechargeStation()).isEqualTo(new WorldSpec.RechargeStation(1, -4, 0.3));
        assertThat(second.rechargeStations()).as("every station still, its own first")
                .containsExactly(new WorldSpec.RechargeStation(1, -4, 0.3), new WorldSpec.RechargeStation(-1, -4, 0.3));
        assertThat(second.robot()).isEqualTo(w.robots().get(1).robot());
    }

    @Test
    void aOneRobotFileMeansWhatItAlwaysMeant() {
        WorldSpec w = WorldFiles.parse(WorldFilesTest.COMPLETE_EXAMPLE);
        WorldSpec asBefore = new WorldSpec(w.name(), w.timeStepMs(), w.maxSimTimeS(), w.seed(), w.arena(), w.robot(),
                w.obstacles(), w.checkpoints(), w.checkpointRadiusM(), w.rechargeStation(), w.battery());
        assertThat(w).isEqualTo(asBefore);
        assertThat(w.robots()).containsExactly(new WorldSpec.RobotEntry(WorldSpec.SINGLE_ROBOT_ID, w.robot(), w.checkpoints()));
        assertThat(w.hasSeveralRobots()).isFalse();
        // a one-robot world may list its stations with rechargeStations too
        WorldSpec stations = WorldFiles.parse(WorldFilesTest.MINIMAL.replace("\"rechargeStation\": { \"x\": -1, \"y\": 0, \"radiusM\": 0.3 }",
                "\"rechargeStations\": [ { \"x\": -1, \"y\": 0, \"radiusM\": 0.3 }, { \"x\": 2, \"y\": 0, \"radiusM\": 0.3 } ]"));
        assertThat(stations.rechargeStations()).hasSize(2);
        assertThat(stations.hasSeveralRobots()).isFalse();
    }

    @Test
    void idsArePositiveIntegersAndDistinct() {
        assertThat(problems(fleetWith("\"id\": 2,", "\"id\": 1,")))
                .containsExactly("robots[1].id: 1 is robots[0]'s id too; ids must be distinct");
        assertThat(problems(fleetWith("\"id\": 2,", "\"id\": 0,")))
                .containsExactly("robots[1].id: must be a positive integer (the robot's robot_id), got 0");
        assertThat(problems(fleetWith("\"id\": 2,", "\"id\": 1.5,")))
                .containsExactly("robots[1].id: must be a positive integer (the robot's robot_id), got 1.5");
        assertThat(problems(fleetWith("\"id\": 2,", "\"id\": \"two\",")))
                .containsExactly("robots[1].id: expected an integer, got a string (\"two\")");
        assertThat(problems(fleetWith("\"id\": 2,", ""))).containsExactly("robots[1].id: missing required key");
    }

    @Test
    void aRobotStartingInsideAnotherIsNamed() {
        List<String> p = problems(fleetWith("\"x\": 3.0, \"y\": 0.5, \"headingDeg\": 180", "\"x\": -2.8, \"y\": 0.1, \"headingDeg\": 180"));
        assertThat(p).containsExactly("robots[1]: start (-2.80, 0.10) is inside robots[0] (start (-3.00, 0.00)): the centres"
                + " are 0.22 m apart, closer than the radii's sum 0.27 m");
        // just clear: centres 0.3 m apart, the radii sum to 0.27 m
        WorldFiles.parse(fleetWith("\"x\": 3.0, \"y\": 0.5, \"headingDeg\": 180", "\"x\": -2.73, \"y\": 0.0, \"headingDeg\": 180"));
    }

    @Test
    void startsAndCheckpointsArePlacedLikeTheOneRobotsWithTheirKeyPaths() {
        assertThat(problems(fleetWith("{ \"x\": 0.0, \"y\": 3.0 }", "{ \"x\": 0.1, \"y\": -2.0 }")))
                .containsExactly("robots[1].checkpoints[1]: checkpoint (0.10, -2.00) is inside obstacle obstacles[0]:"
                        + " the robot (radius 0.15 m) would overlap it");
        assertThat(problems(fleetWith("\"x\": 3.0, \"y\": 0.5, \"headingDeg\": 180", "\"x\": 4.9, \"y\": 0.5, \"headingDeg\": 180")))
                .singleElement().asString().startsWith("robots[1]: start (4.90, 0.50) is outside the arena");
        assertThat(problems(fleetWith("\"x\": -3.0, \"y\": 0.0, \"headingDeg\": 0", "\"x\": 0.0, \"y\": -1.8, \"headingDeg\": 0")))
                .singleElement().asString().startsWith("robots[0]: start (0.00, -1.80) is inside obstacle obstacles[0]");
        assertThat(problems(fleetWith("{ \"x\": 3.0, \"y\": 0.0 }", "{ \"x\": 3.0, \"y\": \"far\" }")))
                .containsExactly("robots[0].checkpoints[0].y: expected a number, got a string (\"far\")");
        assertThat(problems(fleetWith("\"radiusM\": 0.15,", "\"radiusM\": 0.15, \"speed\": 1,")))
                .singleElement().asString().startsWith("robots[1].speed: unknown key");
        assertThat(problems(fleetWith("\"radiusM\": 0.15,", "\"radiusM\": 0.15, \"sensorAnglesDeg\": [10, 5],")))
                .singleElement().asString().startsWith("robots[1].sensorAnglesDeg[1]: the angles must increase");
        assertThat(problems(fleetWith("\"checkpoints\": [ { \"x\": 3.0, \"y\": 0.0 } ]", "\"checkpoints\": []")))
                .containsExactly("robots[0].checkpoints: must list at least one checkpoint");
        assertThat(problems(fleetWith(", \"checkpoints\": [ { \"x\": 3.0, \"y\": 0.0 } ]", "")))
                .containsExactly("robots[0].checkpoints: missing required key");
        assertThat(problems(fleetWith("{ \"x\": 1, \"y\": -4, \"radiusM\": 0.3 }", "{ \"x\": 1, \"y\": -4.9, \"radiusM\": 0.3 }")))
                .singleElement().asString().startsWith("rechargeStations[1]: station (1.00, -4.90) is outside the arena");
    }

    @Test
    void robotsDoNotMixWithRobotCheckpointsOrAStationKeyWithTheOther() {
        assertThat(problems(fleetWith("\"robots\":", "\"robot\": { \"x\": 0, \"y\": 0, \"headingDeg\": 0 }, \"robots\":")))
                .containsExactly("robot: a world with \"robots\" describes each robot there; give robots or robot, not both");
        assertThat(problems(fleetWith("\"robots\":", "\"checkpoints\": [ { \"x\": 1, \"y\": 1 } ], \"robots\":")))
                .containsExactly("checkpoints: a world with \"robots\" gives each robot its checkpoints in its entry;"
                        + " give robots or checkpoints, not both");
        assertThat(problems(fleetWith("\"rechargeStations\":", "\"rechargeStation\": { \"x\": 0, \"y\": -4, \"radiusM\": 0.3 },"
                + " \"rechargeStations\":")))
                .containsExactly("rechargeStation: give rechargeStation (one) or rechargeStations (several), not both");
        assertThat(problems(fleetWith("\"rechargeStations\": [ { \"x\": -1, \"y\": -4, \"radiusM\": 0.3 }, { \"x\": 1, \"y\": -4, \"radiusM\": 0.3 } ]",
                "\"rechargeStations\": []"))).containsExactly("rechargeStations: must list at least one station");
        assertThat(problems(fleetWith("\"radiusM\": 0.3 }, { \"x\": 1", "\"radiusM\": 0.3 }, { \"y\": 1")))
                .containsExactly("rechargeStations[1].x: missing required key");
    }

    @Test
    void anEmptyOrMistypedRobotsListIsNamed() {
        String empty = FLEET.substring(0, FLEET.indexOf("\"robots\": [") + 11) + " ]" + FLEET.substring(FLEET.indexOf("],\n  \"obstacles\"") + 1);
        assertThat(problems(empty)).containsExactly("robots: must list at least one robot");
        assertThat(problems(empty.replace("\"robots\": [ ]", "\"robots\": {}"))).containsExactly("robots: expected an array, got an object");
        assertThat(problems(empty.replace("\"robots\": [ ]", "\"robots\": [ 7 ]")))
                .containsExactly("robots[0]: expected an object, got a number (7)");
    }

    @Test
    void aWorldOnAMapTakesRobotsToo(@TempDir Path dir) throws Exception {
        // a 4 x 2 m map (0.5 m cells): free but for one occupied cell in the middle
        Files.writeString(dir.resolve("room.map"), """
                type octile
                height 4
                width 8
                map
                ........
                ........
                ...@....
                ........
                """);
        String world = """
                { "name": "on-a-map", "map": { "file": "room.map", "cellM": 0.5 },
                  "robots": [
                    { "id": 7, "x": 0.3, "y": 0.3, "headingDeg": 0, "checkpoints": [ { "x": 3.6, "y": 1.7 } ] },
                    { "id": 9, "x": 3.6, "y": 0.3, "headingDeg": 180, "checkpoints": [ { "x": 1.75, "y": 0.75 } ] }
                  ],
                  "rechargeStation": { "x": 0.4, "y": 1.6, "radiusM": 0.3 } }
                """;
        Path file = dir.resolve("world.json");
        Files.writeString(file, world);
        WorldValidationException e = catchThrowableOfType(WorldValidationException.class, () -> WorldFiles.load(file));
        assertThat(e.problems()).singleElement().asString()
                .startsWith("robots[1].checkpoints[0]: checkpoint (1.75, 0.75) is on a wall of the map");
        Files.writeString(file, world.replace("{ \"x\": 1.75, \"y\": 0.75 }", "{ \"x\": 0.3, \"y\": 1.0 }"));
        WorldSpec w = WorldFiles.load(file);
        assertThat(w.robots()).extracting(WorldSpec.RobotEntry::id).containsExactly(7, 9);
        assertThat(w.obstacles()).isNotEmpty();
    }

    @Test
    void theSvgDrawsEveryRobotsStartAndCheckpointsInItsColourAndEveryStation() {
        String svg = new SvgRenderer(WorldFiles.parse(FLEET)).render();
        assertThat(svg).contains("<g id=\"start-1\" stroke=\"#103060\"", "<g id=\"start-2\" stroke=\"#b03060\"",
                ">robot 1</text>", ">robot 2</text>", "<g id=\"station-1\">", "<g id=\"station-2\">", ">recharge 2</text>");
        // three checkpoints, each numbered "robot.checkpoint" in its robot's colour
        assertThat(svg).contains("fill=\"#103060\">1.1</text>", "fill=\"#b03060\">2.1</text>", "fill=\"#b03060\">2.2</text>");
        assertThat(svg.split("stroke-dasharray", -1)).hasSize(4);
        assertThat(svg).doesNotContain("<g id=\"start\" ", "<g id=\"station\">");
    }

    @Test
    void eachRobotsPathAndBodyAreDrawnInItsColourAndSize() {
        WorldSpec w = WorldFiles.parse(FLEET);
        String svg = new SvgRenderer(w)
                .robotPath(1, List.of(new SvgRenderer.TrajectoryPoint(3.0, 0.5, "Move"), new SvgRenderer.TrajectoryPoint(2.0, 0.5, "Move")))
                .robotAt(1, new SvgRenderer.RobotPose(2.0, 0.5, Math.PI, new double[] {0.0}, new double[] {0.4}, 1.0))
                .render();
        assertThat(svg).contains("<polyline id=\"path-2\" fill=\"none\" stroke=\"#b03060\"", "points=\"3.000,-0.500 2.000,-0.500 \"",
                "<g id=\"robot-2\">", "r=\"0.150\" fill=\"#b03060\"", "stroke=\"#e03030\"");
        assertThat(svg).doesNotContain("path-1", "robot-1", "<g id=\"trajectory\"");
    }

    /**
     * A one-robot picture is byte for byte what it was before fleets: the SHA-256 of each bundled world drawn with a
     * trajectory, a marker and a robot with rays, taken from main's jar before fleets (commit dca69ff).
     */
    @Test
    void oneRobotPicturesAreByteForByteAsBeforeFleets() throws Exception {
        Map<String, String> before = Map.of(
                "reference-arena", "aa6c9b9ce2df159c5c04107c542620ae828f869f9b49007086dfb6f359d706ec",
                "obstacle-across-path", "4e3b9081a8591fbc0de69367a6cf09c3b45648a083fe41044c973c5bdca581c0",
                "cluttered-arena", "f50c5bfec1d711ae75bef13d5d48aa5897cf21e045be5a221fb874aa05e64169",
                "low-battery", "e33e5a5213361e12417484a0144a24507f7671ad3b05f8bddf95777c67349324");
        for (Map.Entry<String, String> world : before.entrySet()) {
            String svg = new SvgRenderer(WorldFiles.bundled(world.getKey()))
                    .trajectory(List.of(new SvgRenderer.TrajectoryPoint(0, -4, "Move"), new SvgRenderer.TrajectoryPoint(0.5, -3, "Avoid")))
                    .marker(1, 1, "recharge 1")
                    .robot(new SvgRenderer.RobotPose(0.5, -3, 1.0, new double[] {-0.5, 0.5}, new double[] {0.3, 1.0}, 1.0))
                    .render();
            byte[] sha = MessageDigest.getInstance("SHA-256").digest(svg.getBytes(StandardCharsets.UTF_8));
            assertThat(HexFormat.of().formatHex(sha)).as(world.getKey()).isEqualTo(world.getValue());
        }
    }

    @Test
    void aOneRobotPictureIsTheSameWhetherItsStationIsGivenAloneOrInAListOfOne() {
        String list = WorldFilesTest.MINIMAL.replace("\"rechargeStation\": { \"x\": -1, \"y\": 0, \"radiusM\": 0.3 }",
                "\"rechargeStations\": [ { \"x\": -1, \"y\": 0, \"radiusM\": 0.3 } ]");
        assertThat(new SvgRenderer(WorldFiles.parse(list)).render())
                .isEqualTo(new SvgRenderer(WorldFiles.parse(WorldFilesTest.MINIMAL)).render())
                .contains("<g id=\"start\" ", "<g id=\"station\">");
    }
}
