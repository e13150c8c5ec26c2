package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.sim2d.WorldFiles;

/**
 * A world with several robots in two processes (docs/deployment.md), on MariaDB as the compose
 * services' least-privilege users: one {@code robot --world W} process runs the world with every
 * robot's controller, two engine processes share its robots by lease ({@code --robot-ids}; one
 * serves two robots on one thread, the other one). In sync timing every robot's run is the one
 * {@code run} gives in one process, on H2 and on the direct link, whatever the threads; each engine
 * drives its robot with that robot's own body (a larger, slower robot among them).
 */
class FleetTwoProcessTest {

    /** Three short hops side by side; robot 2 is larger and slower, and ends last. */
    static final String THREE_HOPS = """
            {"name": "three-hops", "arena": {"radiusM": 3.0},
             "robots": [
              {"id": 1, "x": -1.5, "y": -1.5, "headingDeg": 90, "checkpoints": [{"x": -1.5, "y": 0.2}]},
              {"id": 2, "x": 1.5, "y": -1.5, "headingDeg": 90, "radiusM": 0.16, "maxSpeedMps": 0.35,
               "checkpoints": [{"x": 1.2, "y": 0.2}]},
              {"id": 3, "x": 0.5, "y": 1.6, "headingDeg": 180, "checkpoints": [{"x": -0.9, "y": 1.6}]}
             ],
             "rechargeStation": {"x": 0.0, "y": -2.2, "radiusM": 0.35}}
            """;

    /** What the simulator and the handshake decide, per robot: equal in every layout. */
    static final List<String> ROBOT_FIELDS = List.of("id", "success", "outcome", "reason", "endSimTimeS",
            "checkpointsReached", "checkpointsTotal", "distanceM", "collisions", "robotCollisions", "minClearanceM",
            "minBattery", "finalBattery", "recharges", "controlSteps", "engineIterations", "commandWins");

    /** The same for the whole run. */
    static final List<String> RUN_FIELDS = List.of("world", "success", "outcome", "checkpointsReached",
            "checkpointsTotal", "simTimeS", "controlSteps", "engineIterations", "distanceM", "collisions",
            "robotCollisions", "minClearanceM", "minBattery", "finalBattery", "recharges", "commandWins");

    @TempDir
    Path tmp;

    @Test
    void oneRobotProcessRunsTheWorldTwoEnginesShareItsRobotsAndEveryRobotsRunIsRunsOwn() throws Exception {
        Path world = Files.writeString(tmp.resolve("three-hops.json"), THREE_HOPS);
        try (Deployment deployment = Deployment.create()) {
            Path logA = tmp.resolve("engine-a.log");
            Path logB = tmp.resolve("engine-b.log");
            Path robotLog = tmp.resolve("robot.log");
            Process engineA = deployment.start("engine", engine("1-2", "1", "engine-a"), logA);
            Process engineB = deployment.start("engine", engine("3", "0", "engine-b"), logB);
            Map<String, String> robotOptions = new LinkedHashMap<>();
            robotOptions.put("--world", world.toString());
            robotOptions.put("--out", tmp.resolve("out").toString());
            robotOptions.put("--log-every", "50");
            robotOptions.put("--mcap", null);
            Process robot = deployment.start("robot", robotOptions, robotLog);
            assertThat(robot.waitFor(240, TimeUnit.SECONDS)).as(Files.readString(robotLog)).isTrue();
            String log = Files.readString(robotLog);
            assertThat(robot.exitValue()).as(log).isZero();
            assertThat(log).contains("World three-hops: 3 robots (ids 1, 2, 3)")
                    .contains("--robot-id 1 is not used") // the compose service's own option, for a one-robot world
                    .contains("the engines acknowledged every run").contains("robot 2: step 50,").doesNotContain("Exception");

            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
            assertThat(report.get("database").getAsString()).isEqualTo("mysql");
            assertThat(report.has("strategy")).isFalse(); // the robot's user may not read the strategy
            assertThat(report.has("ruleFailures")).isFalse();
            assertThat(report.has("poseError")).isFalse();
            JsonArray robots = report.getAsJsonArray("robots");
            assertThat(robots).hasSize(3);
            for (int i = 0; i < 3; i++) {
                assertThat(robots.get(i).getAsJsonObject().has("ruleFailures")).isFalse();
            }

            // each engine drove its robots with their own bodies, as run drives them (robot 1's is the options' default)
            assertThat(Files.readString(logA)).contains("robot 2 drives at up to 0.35 m/s with 0.320 m between its wheels")
                    .contains("robot 1 drives at") // its default profile, among other robots
                    .contains("lease of robot 1 taken").contains("lease of robot 2 taken").doesNotContain("lease of robot 3");
            assertThat(Files.readString(logB)).contains("lease of robot 3 taken");
            assertThat(deployment.queryLong("SELECT ROUND(axle_width_m * 1000) FROM robot_body WHERE robot_id = 2")).isEqualTo(320);
            // every robot shares its world: its process said so, and its engine ranks Yield as run's does
            assertThat(deployment.queryLong("SELECT COUNT(*) FROM robot_body WHERE shared_world")).isEqualTo(3);
            assertThat(deployment.queryLong("SELECT COUNT(DISTINCT robot_id) FROM strategy WHERE scenario = 'Yield'")).isEqualTo(3);
            assertThat(Files.readString(logA)).contains("between its wheels, among other robots");

            MissionReport h2 = new Mission(new MissionOptions(WorldFiles.load(world),
                    Databases.embeddedH2Url("three_hops_" + System.nanoTime()), "sa", "", "safety-first", 1))
                    .run(Files.createDirectories(tmp.resolve("run-h2")));
            MissionReport direct = new Mission(new MissionOptions(WorldFiles.load(world), null, null, null, "safety-first", 1)
                    .withLink(MissionOptions.Link.DIRECT)).threads(3).run(Files.createDirectories(tmp.resolve("run-direct")));
            assertThat(h2.success()).as("the world's missions are accomplished").isTrue();
            assertSameRun(report, h2);
            assertSameRun(report, direct);

            // run.mcap: each robot's topics under /robot/ID, a /decision per control step, read by the reference reader
            Map<String, Long> messages = new java.util.TreeMap<>();
            for (org.proactiverobotics.mcap.McapCheck.ChannelCount c
                    : org.proactiverobotics.mcap.McapCheck.check(tmp.resolve("out/run.mcap")).channels()) {
                messages.put(c.topic(), c.messages());
            }
            for (int i = 0; i < 3; i++) {
                JsonObject r = robots.get(i).getAsJsonObject();
                assertThat(messages.get("/robot/" + r.get("id").getAsInt() + "/decision")).as(messages.toString())
                        .isEqualTo(r.get("controlSteps").getAsLong());
            }
            McapReaderTest.assumeNodeInstalled();
            String read = McapReaderTest.referenceReader(tmp.resolve("out"), "check-fleet.mjs");
            assertThat(read).contains("mcap-reader: 3 robots, ").endsWith(" 0 failed");

            for (Process engine : List.of(engineA, engineB)) {
                engine.destroy(); // SIGTERM: state saved, exit 0
                assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
                assertThat(engine.exitValue()).isZero();
            }
            assertThat(Files.readString(logA)).contains("robot run").contains("finished at step").doesNotContain("Exception");
        }
    }

    /**
     * @param ids      the robots served
     * @param threads  --threads (0: automatic)
     * @param name     --engine-name
     */
    private static Map<String, String> engine(String ids, String threads, String name) {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("--robot-id", null); // the compose service's own robot: replaced by the list
        options.put("--robot-ids", ids);
        options.put("--threads", threads);
        options.put("--engine-name", name);
        options.put("--log-every", "50");
        return options;
    }

    /** The two-process report's ground truth and step counts equal the one-process run's, robot by robot. */
    static void assertSameRun(JsonObject twoProcesses, MissionReport oneProcess) {
        JsonObject one = new Gson().toJsonTree(oneProcess).getAsJsonObject();
        for (String field : RUN_FIELDS) {
            assertThat(twoProcesses.get(field)).as(field).isEqualTo(one.get(field));
        }
        JsonArray two = twoProcesses.getAsJsonArray("robots");
        JsonArray ones = one.getAsJsonArray("robots");
        assertThat(two.size()).isEqualTo(ones.size());
        for (int i = 0; i < two.size(); i++) {
            for (String field : ROBOT_FIELDS) {
                assertThat(two.get(i).getAsJsonObject().get(field)).as("robot " + (i + 1) + " " + field)
                        .isEqualTo(ones.get(i).getAsJsonObject().get(field));
            }
        }
    }
}
