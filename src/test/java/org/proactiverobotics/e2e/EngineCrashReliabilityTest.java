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
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.junit.jupiter.api.io.TempDir;

/**
 * The engine process SIGKILLed at seeded-random moments, at least ten times over one
 * two-process mission on MariaDB (sync timing), and started again each time with the same
 * flags: each restart resumes the robot's run from the saved state, the robot waits meanwhile
 * (it never steps without the engine), and the run is the uninterrupted run, step for step:
 * same ground truth, every checkpoint marked once, at the same simulated time.
 *
 * <p>Seed: {@code -Dproactive.reliability.seed=N} (default 7); kills: {@code -Dproactive.engineKills=N} (default 10).
 */
@Tag("reliability")
class EngineCrashReliabilityTest {

    private static final String WORLD = "reference-arena";

    @TempDir
    Path tmp;

    /**
     * Without noise, and indoors, where the pose is the localiser's estimate from odometry and the
     * scan: a resumed engine must restore that estimate (its filter is the rule's saved state) to
     * drive on as the uninterrupted run did.
     */
    @ParameterizedTest(name = "noise {0}")
    @ValueSource(strings = {"none", "indoor"})
    void theEngineKilledTenTimesResumesEachTimeAndTheRunIsTheUninterruptedOne(String noise) throws Exception {
        long seed = Long.getLong("proactive.reliability.seed", 7);
        int kills = Integer.getInteger("proactive.engineKills", 10);
        Uninterrupted reference = Uninterrupted.of(WORLD, NoiseLevel.of(noise));
        long totalSteps = reference.report().controlSteps();
        Random random = new Random(seed);
        long start = System.nanoTime();
        try (Deployment deployment = Deployment.create(); Clocks clocks = new Clocks(deployment.adminUrl(), 1)) {
            Map<String, String> engineOptions = Map.of("--log-every", "250");
            List<Path> engineLogs = new ArrayList<>();
            engineLogs.add(tmp.resolve("engine-0.log"));
            Process engine = deployment.start("engine", engineOptions, engineLogs.get(0));
            Map<String, String> robotOptions = new LinkedHashMap<>();
            robotOptions.put("--out", tmp.resolve("out").toString());
            robotOptions.put("--noise", noise);
            robotOptions.put("--log-every", "250");
            Path robotLog = tmp.resolve("robot.log");
            Process robot = deployment.start("robot", robotOptions, robotLog);
            clocks.await("the engine acknowledges the run", clocks::engineStep, s -> s >= 0, robot, 60);

            // Kill points spread over the mission (40-100 % of an even share of its steps each), a moment inside an iteration.
            long budget = (totalSteps - 100) / kills;
            List<String> killed = new ArrayList<>();
            long lastServed = 0;
            for (int k = 1; k <= kills; k++) {
                long target = lastServed + Math.max(1, budget * 2 / 5) + random.nextInt((int) Math.max(1, budget * 3 / 5));
                clocks.await("engine serving step " + target, clocks::engineStep, s -> s >= target, robot, 90);
                long jitterNanos = random.nextInt(15_000_000); // 0-15 ms: anywhere in the next robot step and iteration
                long until = System.nanoTime() + jitterNanos;
                while (System.nanoTime() - until < 0) {
                    Thread.onSpinWait();
                }
                engine.toHandle().destroyForcibly(); // SIGKILL
                assertThat(engine.waitFor(10, TimeUnit.SECONDS)).isTrue();
                assertThat(engine.exitValue()).isEqualTo(137);
                long served = clocks.engineStep();
                Thread.sleep(100); // the robot finishes the step the engine served last, senses the next, waits
                long robotStep = clocks.robotStep();
                long robotSimMs = clocks.robotSimTimeMs();
                long saved = clocks.savedIteration();
                killed.add("kill " + k + ": served " + served + ", robot step " + robotStep + ", saved iteration " + saved);
                // Crash consistency: nothing of an iteration whose state was not saved is in the database.
                assertThat(clocks.value("SELECT COUNT(*) FROM engine_comments WHERE robot_id = ? AND iteration > "
                        + saved)).as("commands of unsaved iterations (%s)", killed).isZero();
                assertThat(clocks.value("SELECT COUNT(*) FROM sensor_requests WHERE robot_id = ? AND iteration > "
                        + saved)).as("requests of unsaved iterations (%s)", killed).isZero();

                // The engine away: the robot waits where it is, on its last served step.
                Thread.sleep(100 + random.nextInt(400));
                assertThat(clocks.robotStep()).as("robot steps while the engine is dead (%s)", killed).isEqualTo(robotStep);
                assertThat(clocks.robotSimTimeMs()).isEqualTo(robotSimMs);
                assertThat(robotStep).as("the robot never runs ahead of the engine").isLessThanOrEqualTo(served + 1);
                assertThat(robot.isAlive()).as(Files.readString(robotLog)).isTrue();

                Path log = tmp.resolve("engine-" + k + ".log");
                engineLogs.add(log);
                engine = deployment.start("engine", engineOptions, log);
                Deployment.awaitLog(log, "resuming robot run", 60);
                lastServed = clocks.await("engine back", clocks::engineStep, s -> s > served, robot, 60);
            }
            assertThat(robot.waitFor(180, TimeUnit.SECONDS)).as("robot finished").isTrue();
            String robotText = Files.readString(robotLog);
            assertThat(robot.exitValue()).as(robotText).isZero();
            engine.destroy();
            assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
            assertThat(engine.exitValue()).isZero();

            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
            System.out.printf("engine SIGKILLed %d times (seed %d) over a %d-step two-process mission: %.1f s wall%n  %s%n",
                    kills, seed, totalSteps, (System.nanoTime() - start) / 1e9, String.join("\n  ", killed));
            assertThat(report.get("outcome").getAsString()).isEqualTo("MISSION_ACCOMPLISHED");
            assertThat(report.get("checkpointsReached").getAsInt()).isEqualTo(report.get("checkpointsTotal").getAsInt());
            assertThat(report.get("collisions").getAsInt()).isZero();
            TwoProcessMissionTest.assertSameGroundTruth(report, reference.report());

            // Every checkpoint marked once, in order, at the uninterrupted run's simulated times.
            List<Clocks.CheckpointRow> rows = clocks.checkpoints();
            assertThat(rows).isEqualTo(reference.checkpoints());
            assertMarkedOnceInOrder(rows);
            // Each restart resumed the same run; none started it afresh.
            for (int k = 1; k < engineLogs.size(); k++) {
                assertThat(Files.readString(engineLogs.get(k))).contains("resuming robot run").doesNotContain("new robot run")
                        .doesNotContain("Exception");
            }
            assertThat(Files.readString(engineLogs.get(0))).contains("new robot run");
            assertThat(clocks.savedIteration()).isEqualTo(totalSteps);
            assertThat(robotText).doesNotContain("Exception");
        }
    }

    /**
     * The checkpoints rows of an accomplished run: each marked with a simulated time, the times
     * increasing with seq. The last one may be unmarked: the robot ends the run on the simulator's
     * ground truth in the step it reaches it, as the one-process mission does, before the engine's
     * iteration that would mark it.
     */
    static void assertMarkedOnceInOrder(List<Clocks.CheckpointRow> rows) {
        assertThat(rows).isNotEmpty();
        List<Clocks.CheckpointRow> marked = rows.subList(0, rows.size() - 1);
        assertThat(marked).allMatch(r -> r.reached() && r.reachedSimTimeMs() != null && r.reachedSimTimeMs() > 0);
        for (int i = 1; i < marked.size(); i++) {
            assertThat(marked.get(i).reachedSimTimeMs()).isGreaterThan(marked.get(i - 1).reachedSimTimeMs());
        }
        Clocks.CheckpointRow last = rows.get(rows.size() - 1);
        if (last.reached()) {
            assertThat(last.reachedSimTimeMs()).isGreaterThan(marked.isEmpty() ? 0 : marked.get(marked.size() - 1).reachedSimTimeMs());
        } else {
            assertThat(last.reachedSimTimeMs()).as("an unmarked checkpoint's time: none (the seed writes 0)").isIn(null, 0L);
        }
    }
}
