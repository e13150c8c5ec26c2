package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.sim2d.WorldFiles;

/**
 * One engine process serving the four robots of one world ({@code --robot-ids 1-4}), the world in
 * one robot process, on MariaDB in sync timing: the engine is SIGKILLed at seeded-random moments
 * and started again with the same flags, several times. While it is dead no robot of the world
 * steps; each restart resumes every robot's run from its saved state; and every robot's run is the
 * uninterrupted one-process run's, step for step.
 *
 * <p>Seed: {@code -Dproactive.reliability.seed=N} (default 7); kills: {@code -Dproactive.fleetEngineKills=N} (default 5).
 */
@Tag("reliability")
class FleetEngineCrashReliabilityTest {

    /** Four robots, each going round its own quadrant (one larger, one slower), a pillar in the middle. */
    static final String FOUR_QUADRANTS = """
            {"name": "four-quadrants", "arena": {"widthM": 7.0, "heightM": 7.0},
             "robots": [
              {"id": 1, "x": -2.5, "y": -2.5, "headingDeg": 0,
               "checkpoints": [{"x": -1.0, "y": -2.5}, {"x": -1.0, "y": -1.0}, {"x": -2.5, "y": -1.2}]},
              {"id": 2, "x": 2.5, "y": -2.5, "headingDeg": 90, "radiusM": 0.15,
               "checkpoints": [{"x": 2.5, "y": -1.0}, {"x": 1.0, "y": -1.0}, {"x": 1.2, "y": -2.5}]},
              {"id": 3, "x": 2.5, "y": 2.5, "headingDeg": 180, "maxSpeedMps": 0.4,
               "checkpoints": [{"x": 1.0, "y": 2.5}, {"x": 1.0, "y": 1.0}, {"x": 2.5, "y": 1.2}]},
              {"id": 4, "x": -2.5, "y": 2.5, "headingDeg": 270,
               "checkpoints": [{"x": -2.5, "y": 1.0}, {"x": -1.0, "y": 1.0}, {"x": -1.2, "y": 2.5}]}
             ],
             "obstacles": [{"shape": "circle", "x": 0.0, "y": 0.0, "radiusM": 0.5}],
             "rechargeStation": {"x": 0.0, "y": -3.0, "radiusM": 0.35}}
            """;

    private static final String SERVED = "SELECT COALESCE(MAX(step), 0) FROM engine_clock WHERE robot_id BETWEEN 1 AND 4";
    private static final String STEPPED = "SELECT COALESCE(MAX(step), 0) FROM robot_clock WHERE robot_id BETWEEN 1 AND 4";

    @TempDir
    Path tmp;

    @Test
    void theEngineOfFourRobotsKilledAndRestartedResumesEveryRobotAndEachRunIsTheUninterruptedOne() throws Exception {
        long seed = Long.getLong("proactive.reliability.seed", 7);
        int kills = Integer.getInteger("proactive.fleetEngineKills", 5);
        Path world = Files.writeString(tmp.resolve("four-quadrants.json"), FOUR_QUADRANTS);
        MissionReport reference = new Mission(new MissionOptions(WorldFiles.load(world),
                Databases.embeddedH2Url("four_quadrants_" + System.nanoTime()), "sa", "", "safety-first", 1))
                .run(Files.createDirectories(tmp.resolve("reference")));
        assertThat(reference.success()).isTrue();
        long totalSteps = reference.robots().stream().mapToLong(r -> r.controlSteps()).min().orElseThrow();
        Random random = new Random(seed);
        long start = System.nanoTime();
        try (Deployment deployment = Deployment.create()) {
            Map<String, String> engineOptions = new LinkedHashMap<>();
            engineOptions.put("--robot-id", null);
            engineOptions.put("--robot-ids", "1-4");
            engineOptions.put("--log-every", "100");
            List<Path> engineLogs = new ArrayList<>();
            engineLogs.add(tmp.resolve("engine-0.log"));
            Process engine = deployment.start("engine", engineOptions, engineLogs.get(0));
            Map<String, String> robotOptions = new LinkedHashMap<>();
            robotOptions.put("--world", world.toString());
            robotOptions.put("--out", tmp.resolve("out").toString());
            robotOptions.put("--log-every", "100");
            Path robotLog = tmp.resolve("robot.log");
            Process robot = deployment.start("robot", robotOptions, robotLog);
            Deployment.awaitLog(robotLog, "the engines acknowledged every run", 120);

            // kill points spread over the shortest robot's mission, each a moment inside a step
            long budget = (totalSteps - 40) / kills;
            List<String> killed = new ArrayList<>();
            long lastServed = 0;
            for (int k = 1; k <= kills; k++) {
                long target = lastServed + Math.max(1, budget * 2 / 5) + random.nextInt((int) Math.max(1, budget * 3 / 5));
                await(deployment, SERVED, target, robot, robotLog);
                Thread.sleep(random.nextInt(15));
                engine.toHandle().destroyForcibly(); // SIGKILL
                assertThat(engine.waitFor(10, TimeUnit.SECONDS)).isTrue();
                assertThat(engine.exitValue()).isEqualTo(137);
                long served = deployment.queryLong(SERVED);
                Thread.sleep(300); // the world finishes the step its engines served last, senses the next, waits
                long stepped = deployment.queryLong(STEPPED);
                killed.add("kill " + k + ": served " + served + ", world step " + stepped);
                Thread.sleep(200 + random.nextInt(400));
                assertThat(deployment.queryLong(STEPPED)).as("the world steps while its engine is dead (%s)", killed)
                        .isEqualTo(stepped);
                assertThat(stepped).as("the world never runs ahead of its engine").isLessThanOrEqualTo(served + 1);
                assertThat(robot.isAlive()).as(Files.readString(robotLog)).isTrue();

                Path log = tmp.resolve("engine-" + k + ".log");
                engineLogs.add(log);
                engine = deployment.start("engine", engineOptions, log);
                Deployment.awaitLog(log, "resuming robot run", 90);
                lastServed = await(deployment, SERVED, served + 1, robot, robotLog);
            }
            assertThat(robot.waitFor(300, TimeUnit.SECONDS)).as("robot process finished").isTrue();
            String robotText = Files.readString(robotLog);
            assertThat(robot.exitValue()).as(robotText).isZero();
            engine.destroy();
            assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
            assertThat(engine.exitValue()).isZero();
            System.out.printf("engine of four robots SIGKILLed %d times (seed %d): %.1f s wall%n  %s%n", kills, seed,
                    (System.nanoTime() - start) / 1e9, String.join("\n  ", killed));

            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
            assertThat(report.get("outcome").getAsString()).isEqualTo("MISSION_ACCOMPLISHED");
            FleetTwoProcessTest.assertSameRun(report, reference);
            for (int k = 1; k < engineLogs.size(); k++) { // each restart resumed the runs; none started one afresh
                assertThat(Files.readString(engineLogs.get(k))).contains("resuming robot run").doesNotContain("new robot run")
                        .doesNotContain("Exception");
            }
            assertThat(Files.readString(engineLogs.get(0))).contains("new robot run");
            assertThat(robotText).doesNotContain("Exception");
        }
    }

    /** Waits until the query's value reaches the target while the robot process lives; returns the value. */
    private static long await(Deployment deployment, String query, long target, Process robot, Path robotLog)
            throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (true) {
            long value = deployment.queryLong(query);
            if (value >= target) {
                return value;
            }
            assertThat(robot.isAlive()).as(Files.readString(robotLog)).isTrue();
            assertThat(System.nanoTime() < deadline).as("step %d not reached in 120 s (at %d)", target, value).isTrue();
            Thread.sleep(5);
        }
    }
}
