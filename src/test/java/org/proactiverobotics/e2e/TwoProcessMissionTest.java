package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.Main;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.sim2d.WorldFiles;
import picocli.CommandLine;

/**
 * The paper's deployment without Docker: the compose services' engine and robot commands as two
 * OS processes, as the least-privilege users the compose init scripts create, on MariaDB
 * through the MySQL driver compose uses. In sync timing the robot process's ground truth equals
 * the one-process {@code run}'s, whichever process starts first.
 */
class TwoProcessMissionTest {

    /** A short hop: one checkpoint 1.5 m ahead, for the cases where the mission itself does not matter. */
    static final String SHORT_HOP = """
            {"name": "short-hop", "arena": {"radiusM": 3.0}, "robot": {"x": 0.0, "y": -1.0, "headingDeg": 90.0},
             "checkpoints": [{"x": 0.0, "y": 0.5}], "rechargeStation": {"x": -2.0, "y": 0.0, "radiusM": 0.35}}
            """;

    private static Deployment deployment;

    @TempDir
    Path tmp;

    @BeforeAll
    static void deploy() throws Exception {
        deployment = Deployment.create();
    }

    @AfterAll
    static void tearDown() throws Exception {
        if (deployment != null) {
            deployment.close();
        }
    }

    @Test
    void engineFirstThenRobotGiveRunsGroundTruthThenSigtermSavesAndExitsZero() throws Exception {
        Path engineLog = tmp.resolve("engine.log");
        Path robotLog = tmp.resolve("robot.log");
        Process engine = deployment.start("engine", Map.of("--heartbeat", tmp.resolve("engine.beat").toString()), engineLog);
        Deployment.awaitLog(engineLog, "waiting for the robot", 30);

        long start = System.nanoTime();
        Process robot = deployment.start("robot", Map.of("--out", tmp.resolve("out").toString(),
                "--heartbeat", tmp.resolve("robot.beat").toString()), robotLog);
        assertThat(robot.waitFor(150, TimeUnit.SECONDS)).as("robot finished").isTrue();
        double wallS = (System.nanoTime() - start) / 1e9;
        assertThat(robot.exitValue()).as(Files.readString(robotLog)).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
        assertSameGroundTruth(report, Missions.onH2("reference-arena").report());
        assertThat(report.get("database").getAsString()).isEqualTo("mysql");
        // the robot's user may read neither the strategy nor rule_failures: left out, not made up (it was -1)
        assertThat(report.has("strategy")).isFalse();
        assertThat(report.has("ruleFailures")).isFalse();
        // nor can it see what the engine believed: no pose error rather than a made-up one
        assertThat(report.has("poseError")).isFalse();
        assertThat(Files.readString(robotLog)).contains("the engine acknowledged run").contains("robot 1: step 500,")
                .doesNotContain("Exception");
        assertThat(tmp.resolve("robot.beat")).exists();
        // in sync timing on MariaDB each side waits for the other's step in the server, not by polling
        long steps = report.get("controlSteps").getAsLong();
        Matcher robotWaits = Pattern.compile("handshake: (\\d+) steps served, (\\d+) of them seen at the first look")
                .matcher(Files.readString(robotLog));
        assertThat(robotWaits.find()).as(Files.readString(robotLog)).isTrue();
        assertThat(Long.parseLong(robotWaits.group(1))).isEqualTo(steps);
        assertThat(Long.parseLong(robotWaits.group(2))).as("steps seen served at the robot's first look").isGreaterThan(steps * 9 / 10);
        Matcher robotTimeOuts = Pattern.compile("handshake: (\\d+) waits on the engine's locks in the database, (\\d+) of them timed out")
                .matcher(Files.readString(robotLog));
        assertThat(robotTimeOuts.find()).as(Files.readString(robotLog)).isTrue();
        // a wait times out only when the engine's iteration takes over 200 ms: on a loaded machine a few do (6 seen at load 16)
        assertThat(Long.parseLong(robotTimeOuts.group(2))).as("the robot's waits that timed out (200 ms each)").isLessThanOrEqualTo(steps / 100);
        System.out.printf("two-process reference mission (MariaDB, sync): %.1f s wall, robot loop %.1f s%n", wallS,
                report.get("wallTimeS").getAsDouble());

        // the strategy of the mission, from a third process's point of view, as the engine's user
        String shown = strategy(0);
        assertThat(shown).contains("strategy safety-first").contains("ObstacleAvoidance");
        assertThat(strategy(0, "--set", "destination-first")).contains("safety-first -> destination-first")
                .contains("strategy destination-first");
        assertThat(strategy(2, "--set", "reckless")).contains("unknown strategy 'reckless'").contains("safety-first, destination-first");

        engine.destroy(); // SIGTERM
        assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(engine.exitValue()).as(Files.readString(engineLog)).isZero();
        Matcher engineWaits = Pattern.compile("handshake: (\\d+) waits on the robot's locks in the database, (\\d+) of them timed out")
                .matcher(Files.readString(engineLog));
        assertThat(engineWaits.find()).as(Files.readString(engineLog)).isTrue();
        assertThat(Long.parseLong(engineWaits.group(1))).as("the engine's waits in the server").isGreaterThan(steps * 9 / 10);
        assertThat(Long.parseLong(engineWaits.group(2))).as("the engine's waits that timed out (200 ms each)").isLessThanOrEqualTo(5);
        assertThat(Files.readString(engineLog)).contains("stopped after iteration " + report.get("controlSteps").getAsLong())
                .contains("engine 1: iteration 500 for robot step 500").doesNotContain("Exception");
        assertThat(deployment.queryLong("SELECT iteration FROM engine_state WHERE robot_id = 1"))
                .isEqualTo(report.get("controlSteps").getAsLong());
    }

    @Test
    void robotFirstThenEngineGiveRunsGroundTruth() throws Exception {
        Path world = tmp.resolve("short-hop.json");
        Files.writeString(world, SHORT_HOP);
        Path engineLog = tmp.resolve("engine.log");
        Path robotLog = tmp.resolve("robot.log");
        Process robot = deployment.start("robot", robotOptions(world, "2"), robotLog);
        Deployment.awaitLog(robotLog, "waiting for the engine to acknowledge run", 30);
        Process engine = deployment.start("engine", Map.of("--robot-id", "2", "--log-every", "50"), engineLog);
        assertThat(robot.waitFor(90, TimeUnit.SECONDS)).isTrue();
        assertThat(robot.exitValue()).as(Files.readString(robotLog)).isZero();
        engine.destroy();
        assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(engine.exitValue()).as(Files.readString(engineLog)).isZero();

        JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
        Path runOut = Files.createDirectories(tmp.resolve("run"));
        MissionReport oneProcess = new Mission(new MissionOptions(WorldFiles.load(world),
                Databases.embeddedH2Url("short_hop_" + System.nanoTime()), "sa", "", "safety-first", 1)).run(runOut);
        assertSameGroundTruth(report, oneProcess);
    }

    @Test
    void oneEngineThreadServingTwoRobotsRunsTheirIterationsAsOneBatchAndGivesEachItsOwnRun() throws Exception {
        Path hop = tmp.resolve("short-hop.json");
        Files.writeString(hop, SHORT_HOP);
        Path other = tmp.resolve("other-hop.json");
        Files.writeString(other, SHORT_HOP.replace("short-hop", "other-hop").replace("{\"x\": 0.0, \"y\": 0.5}",
                "{\"x\": 0.8, \"y\": 0.6}"));
        Path engineLog = tmp.resolve("engine.log");
        Map<String, String> engineOptions = new LinkedHashMap<>();
        engineOptions.put("--robot-id", null); // the compose service's own robot: replaced by the two
        engineOptions.put("--robot-ids", "7-8");
        engineOptions.put("--threads", "1"); // both robots on one thread, so that their tables are read together
        engineOptions.put("--log-every", "50");
        Process engine = deployment.start("engine", engineOptions, engineLog);
        Map<Integer, Process> robots = new LinkedHashMap<>();
        Map<Integer, Path> worlds = Map.of(7, hop, 8, other);
        for (int id : worlds.keySet()) {
            Map<String, String> options = robotOptions(worlds.get(id), String.valueOf(id));
            options.put("--out", tmp.resolve("out-" + id).toString());
            options.put("--heartbeat", tmp.resolve("robot-" + id + ".beat").toString());
            robots.put(id, deployment.start("robot", options, tmp.resolve("robot-" + id + ".log")));
        }
        for (int id : robots.keySet()) {
            assertThat(robots.get(id).waitFor(90, TimeUnit.SECONDS)).as(Files.readString(engineLog)).isTrue();
            assertThat(robots.get(id).exitValue()).as(Files.readString(tmp.resolve("robot-" + id + ".log"))).isZero();
        }
        engine.destroy();
        assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
        String log = Files.readString(engineLog);
        assertThat(engine.exitValue()).as(log).isZero();
        Matcher batches = Pattern.compile("robots 7-8: (\\d+) of their \\d+ iterations run in (\\d+) batches").matcher(log);
        assertThat(batches.find()).as(log).isTrue();
        assertThat(Long.parseLong(batches.group(2))).as("passes with both robots due").isPositive();
        assertThat(log).doesNotContain("Exception");
        for (int id : worlds.keySet()) { // each robot's run is the one it has alone, step for step
            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out-" + id + "/report.json"))).getAsJsonObject();
            Path runOut = Files.createDirectories(tmp.resolve("run-" + id));
            MissionReport oneProcess = new Mission(new MissionOptions(WorldFiles.load(worlds.get(id)),
                    Databases.embeddedH2Url("hop_" + id + "_" + System.nanoTime()), "sa", "", "safety-first", 1)).run(runOut);
            assertSameGroundTruth(report, oneProcess);
        }
    }

    @Test
    void aRobotOfABatchLostToAnotherEngineAndTakenBackEndsItsOwnRunAndSoDoesTheOther() throws Exception {
        Path world = tmp.resolve("long-hop.json");
        Files.writeString(world, SHORT_HOP.replace("short-hop", "long-hop").replace("\"y\": -1.0", "\"y\": -2.2")
                .replace("{\"x\": 0.0, \"y\": 0.5}", "{\"x\": 0.0, \"y\": 2.2}"));
        Path engineLog = tmp.resolve("engine.log");
        Map<String, String> engineOptions = new LinkedHashMap<>();
        engineOptions.put("--robot-id", null);
        engineOptions.put("--robot-ids", "9-10");
        engineOptions.put("--threads", "1");
        engineOptions.put("--lease-s", "1");
        Process engine = deployment.start("engine", engineOptions, engineLog);
        List<Process> robots = new ArrayList<>();
        for (int id = 9; id <= 10; id++) {
            Map<String, String> options = robotOptions(world, String.valueOf(id));
            options.put("--out", tmp.resolve("out-" + id).toString());
            options.put("--heartbeat", tmp.resolve("robot-" + id + ".beat").toString());
            robots.add(deployment.start("robot", options, tmp.resolve("robot-" + id + ".log")));
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (deployment.queryLong("SELECT COALESCE(MIN(step), 0) FROM engine_clock WHERE robot_id IN (9, 10)") < 60
                || deployment.queryLong("SELECT COUNT(*) FROM engine_clock WHERE robot_id IN (9, 10)") < 2) {
            assertThat(System.nanoTime() < deadline).as(Files.readString(engineLog)).isTrue();
            Thread.sleep(5);
        }
        // another engine takes robot 10's lease and lets it lapse at once: the engine's next iteration for
        // robot 10 fails its lease check (robot 9's before it rolls back too when they ran as one batch,
        // EngineLoopBatchTest), then the engine takes robot 10 back and resumes it from its saved state
        deployment.executeAsAdmin("UPDATE engine_lease SET owner = 'thief', epoch = epoch + 1,"
                + " expires_at = CURRENT_TIMESTAMP(3) WHERE robot_id = 10");
        for (int id = 9; id <= 10; id++) {
            Process robot = robots.get(id - 9);
            assertThat(robot.waitFor(90, TimeUnit.SECONDS)).as(Files.readString(engineLog)).isTrue();
            assertThat(robot.exitValue()).as(Files.readString(tmp.resolve("robot-" + id + ".log"))).isZero();
        }
        engine.destroy();
        assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
        String log = Files.readString(engineLog);
        assertThat(engine.exitValue()).as(log).isZero();
        assertThat(log).contains("robot 10 lost to another engine").contains("lease of robot 10 taken (epoch 3)")
                .containsPattern("robots 9-10: \\d+ of their \\d+ iterations run in [1-9]\\d* batches").doesNotContain("Exception");
        MissionReport oneProcess = new Mission(new MissionOptions(WorldFiles.load(world),
                Databases.embeddedH2Url("long_hop_" + System.nanoTime()), "sa", "", "safety-first", 1))
                .run(Files.createDirectories(tmp.resolve("run")));
        for (int id = 9; id <= 10; id++) { // each robot's run is still the one it has alone, step for step
            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out-" + id + "/report.json"))).getAsJsonObject();
            assertSameGroundTruth(report, oneProcess);
        }
    }

    @Test
    void realTimeTimingAccomplishesAShortHop() throws Exception {
        Path world = tmp.resolve("short-hop.json");
        Files.writeString(world, SHORT_HOP);
        Path engineLog = tmp.resolve("engine.log");
        Path robotLog = tmp.resolve("robot.log");
        Process engine = deployment.start("engine", Map.of("--robot-id", "3", "--period-ms", "16"), engineLog);
        Map<String, String> options = robotOptions(world, "3");
        options.put("--timing", "realtime");
        options.put("--real-time-factor", "2");
        Process robot = deployment.start("robot", options, robotLog);
        assertThat(robot.waitFor(90, TimeUnit.SECONDS)).isTrue();
        assertThat(robot.exitValue()).as(Files.readString(robotLog)).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
        assertThat(report.get("outcome").getAsString()).isEqualTo("MISSION_ACCOMPLISHED");
        assertThat(report.get("engineIterations").getAsLong()).isPositive();
        engine.destroy();
        assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(engine.exitValue()).isZero();
        assertThat(Files.readString(engineLog)).contains("realtime timing");
    }

    /**
     * A plug-in in the deployment: the engine process loads it (--scenarios, --strategy-file) and the
     * two processes give the one-process run's ground truth; a third process re-ranks it by name.
     */
    @Test
    void theEngineProcessRunsAPluginAsRunDoesAndAThirdProcessReranksItByName() throws Exception {
        Path jar = PluginJars.slowpoke(tmp);
        Path world = Files.writeString(tmp.resolve("plugin-hop.json"), PluginCommandTest.HOP);
        Path top = Files.writeString(tmp.resolve("top.json"), "{\"name\": \"slow-first\", \"priorities\": {\"Slowpoke\": 9,"
                + " \"ObstacleAvoidance\": 3, \"BatteryMonitor\": 2, \"ReachDestination\": 1}}");
        Path engineLog = tmp.resolve("engine.log");
        Path robotLog = tmp.resolve("robot.log");
        Process engine = deployment.start("engine", Map.of("--robot-id", "5", "--scenarios", jar.toString(),
                "--strategy-file", top.toString()), engineLog);
        Process robot = deployment.start("robot", Map.of("--robot-id", "5", "--world", world.toString(),
                "--out", tmp.resolve("out").toString()), robotLog);
        assertThat(robot.waitFor(90, TimeUnit.SECONDS)).isTrue();
        assertThat(robot.exitValue()).as(Files.readString(robotLog)).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
        assertThat(report.getAsJsonObject("commandWins").get("Slowpoke").getAsLong()).isPositive();

        MissionOptions options = new MissionOptions(WorldFiles.load(world), Databases.embeddedH2Url("plugin_" + System.nanoTime()),
                "sa", "", Strategy.SAFETY_FIRST, 1).withScenarios(
                ScenarioPlugins.load(List.of(jar), RobotEngine.builtInScenarios()), Strategy.read(top));
        MissionReport oneProcess = new Mission(options).run(Files.createDirectories(tmp.resolve("run")));
        TwoProcessMissionTest.assertSameGroundTruth(report, oneProcess);
        assertThat(report.getAsJsonObject("commandWins").get("Slowpoke").getAsLong())
                .isEqualTo(oneProcess.commandWins().get("Slowpoke"));

        String shown = strategy(0, "--robot-id", "5");
        assertThat(shown).contains("strategy slow-first").contains("Slowpoke");
        Path bottom = Files.writeString(tmp.resolve("bottom.json"), "{\"priorities\": {\"ReachDestination\": 5, \"Slowpoke\": 1}}");
        assertThat(strategy(0, "--robot-id", "5", "--set-file", bottom.toString())).contains("slow-first -> bottom")
                .contains("leaves out BatteryMonitor, ObstacleAvoidance");
        assertThat(deployment.queryLong("SELECT priority FROM strategy WHERE robot_id = 5 AND scenario = 'Slowpoke'")).isEqualTo(1);
        assertThat(deployment.queryLong("SELECT slot FROM strategy WHERE robot_id = 5 AND scenario = 'Slowpoke'")).isEqualTo(3);
        Path stranger = Files.writeString(tmp.resolve("stranger.json"), "{\"priorities\": {\"Stranger\": 5}}");
        assertThat(strategy(2, "--robot-id", "5", "--set-file", stranger.toString())).contains("stranger.json")
                .contains("'Stranger', which is not loaded").contains("Slowpoke");

        engine.destroy();
        assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(engine.exitValue()).as(Files.readString(engineLog)).isZero();
    }

    private Map<String, String> robotOptions(Path world, String robotId) {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("--world", world.toString());
        options.put("--robot-id", robotId);
        options.put("--out", tmp.resolve("out").toString());
        options.put("--heartbeat", tmp.resolve("robot.beat").toString());
        return options;
    }

    /** The simulator's ground truth (docs/report.md) and the step counts match, field by field. */
    static void assertSameGroundTruth(JsonObject twoProcesses, MissionReport oneProcess) {
        assertThat(twoProcesses.get("outcome").getAsString()).isEqualTo(oneProcess.outcome().name());
        assertThat(twoProcesses.get("checkpointsReached").getAsInt()).isEqualTo(oneProcess.checkpointsReached());
        assertThat(twoProcesses.get("collisions").getAsInt()).isEqualTo(oneProcess.collisions());
        assertThat(twoProcesses.get("distanceM").getAsDouble()).isEqualTo(oneProcess.distanceM());
        assertThat(twoProcesses.get("controlSteps").getAsLong()).isEqualTo(oneProcess.controlSteps());
        assertThat(twoProcesses.get("engineIterations").getAsLong()).isEqualTo(oneProcess.engineIterations());
        assertThat(twoProcesses.get("minBattery").getAsDouble()).isEqualTo(oneProcess.minBattery());
        assertThat(twoProcesses.get("finalBattery").getAsDouble()).isEqualTo(oneProcess.finalBattery());
        assertThat(twoProcesses.get("minClearanceM").getAsDouble()).isEqualTo(oneProcess.minClearanceM());
        assertThat(twoProcesses.get("simTimeS").getAsDouble()).isEqualTo(oneProcess.simTimeS());
        assertThat(twoProcesses.get("recharges").getAsInt()).isEqualTo(oneProcess.recharges());
    }

    private static String strategy(int expectedCode, String... more) {
        StringWriter out = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(out, true));
        String[] args = new String[6 + more.length];
        args[0] = "strategy";
        args[1] = "--db";
        args[2] = deployment.url();
        args[3] = "--db-user";
        args[4] = deployment.engineUser;
        args[5] = "--db-password=" + Deployment.ENGINE_PASSWORD;
        System.arraycopy(more, 0, args, 6, more.length);
        assertThat(cl.execute(args)).as(out.toString()).isEqualTo(expectedCode);
        return out.toString();
    }
}
