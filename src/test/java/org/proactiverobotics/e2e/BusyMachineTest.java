package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.CleanupMode;
import org.junit.jupiter.api.io.TempDir;

/**
 * The two processes on a busy machine (issue 30): a side that is alive but slow is waited for,
 * never given up on. Two deterministic stand-ins for a machine starved of processor time: a
 * database that takes longer to answer a new connection than the robot's pool waits for one (a
 * robot used to exit 3 there, at its first read), and each process stopped outright
 * ({@code kill -STOP}) for longer than any time-out of the other side, then resumed.
 */
class BusyMachineTest {

    private static final String WORLD = "reference-arena";
    /** Longer than the robot pool's wait for a connection (RobotPool, 500 ms), shorter than its driver's socket time-out. */
    private static final Duration SLOW_ANSWER = Duration.ofMillis(1_500);
    /** Longer than the lease (5 s), the pools' waits for a connection (3 s) and the robot's socket time-out (2 s). */
    private static final Duration STOPPED = Duration.ofSeconds(8);

    @TempDir(cleanup = CleanupMode.ON_SUCCESS) // a failed run keeps its logs and report
    Path tmp;

    @Test
    void aRobotWhoseDatabaseIsSlowToGiveItAConnectionWaitsAndAccomplishesItsMission() throws Exception {
        try (Deployment deployment = Deployment.create(); TcpProxy proxy = new TcpProxy("127.0.0.1", mariaDbPort())) {
            proxy.slowToAnswer(SLOW_ANSWER);
            Path engineLog = tmp.resolve("engine.log");
            Process engine = deployment.start("engine", Map.of(), engineLog);
            Map<String, String> robotOptions = new LinkedHashMap<>();
            robotOptions.put("--db", "jdbc:mysql://127.0.0.1:" + proxy.port() + "/" + deployment.database);
            robotOptions.put("--out", tmp.resolve("out").toString());
            Path robotLog = tmp.resolve("robot.log");
            Process robot = deployment.start("robot", robotOptions, robotLog);

            assertThat(robot.waitFor(180, TimeUnit.SECONDS)).as("robot finished").isTrue();
            String robotText = Files.readString(robotLog);
            assertThat(robot.exitValue()).as(robotText).isZero();
            assertThat(robotText).contains("reading the stored mission failed (attempt 1)")
                    .contains("Connection is not available").contains("stored mission read (attempt")
                    .doesNotContain("\tat ");
            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
            assertThat(report.get("outcome").getAsString()).isEqualTo("MISSION_ACCOMPLISHED");
            engine.destroy();
            assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
            assertThat(engine.exitValue()).as(Files.readString(engineLog)).isZero();
        }
    }

    @Test
    @Tag("reliability") // long (a mission and two 8 s stops: about 40 s): with the long tests, -Preliability
    void theEngineThenTheRobotStoppedLongerThanEveryTimeOutResumeAndTheRunIsTheUninterruptedOne() throws Exception {
        Uninterrupted reference = Uninterrupted.of(WORLD);
        long totalSteps = reference.report().controlSteps();
        try (Deployment deployment = Deployment.create(); Clocks clocks = new Clocks(deployment.adminUrl(), 1)) {
            Path engineLog = tmp.resolve("engine.log");
            Process engine = deployment.start("engine", Map.of("--log-every", "250"), engineLog);
            Map<String, String> robotOptions = new LinkedHashMap<>();
            robotOptions.put("--out", tmp.resolve("out").toString());
            robotOptions.put("--log-every", "250");
            Path robotLog = tmp.resolve("robot.log");
            Process robot = deployment.start("robot", robotOptions, robotLog);

            clocks.await("engine serving a third of the mission", clocks::engineStep, s -> s >= totalSteps / 3, robot, 120);
            pause(engine, STOPPED);
            long servedAfterEngineStop = clocks.await("engine serving again", clocks::engineStep, s -> s >= totalSteps / 3 + 20,
                    robot, 60);
            clocks.await("engine serving two thirds of the mission", clocks::engineStep, s -> s >= 2 * totalSteps / 3, robot, 120);
            pause(robot, STOPPED);

            assertThat(robot.waitFor(180, TimeUnit.SECONDS)).as("robot finished").isTrue();
            String robotText = Files.readString(robotLog);
            assertThat(robot.exitValue()).as(robotText).isZero();
            assertThat(engine.isAlive()).as("the engine served on after both stops").isTrue();
            engine.destroy();
            assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
            String engineText = Files.readString(engineLog);
            assertThat(engine.exitValue()).as(engineText).isZero();

            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
            TwoProcessMissionTest.assertSameGroundTruth(report, reference.report());
            assertThat(clocks.checkpoints()).isEqualTo(reference.checkpoints());
            assertThat(servedAfterEngineStop).isGreaterThan(totalSteps / 3);
            // the robot said it was waiting while the engine was stopped, and went on without a failure
            assertThat(robotText).contains("waiting for the engine to serve step").contains("times the")
                    .doesNotContain("Exception");
            assertThat(engineText).doesNotContain("Exception").doesNotContain("lost to another engine");
        }
    }

    /** Stops a process with SIGSTOP (the JDK cannot), keeps it stopped this long, then resumes it with SIGCONT. */
    private static void pause(Process p, Duration howLong) throws Exception {
        signal(p, "-STOP");
        try {
            Thread.sleep(howLong.toMillis());
        } finally {
            signal(p, "-CONT");
        }
    }

    private static void signal(Process p, String signal) throws Exception {
        Process kill = StartedProcesses.start(new ProcessBuilder("kill", signal, Long.toString(p.pid())).inheritIO());
        assertThat(kill.waitFor(10, TimeUnit.SECONDS) && kill.exitValue() == 0).as("kill " + signal + " " + p.pid()).isTrue();
    }

    private static int mariaDbPort() {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("jdbc:mariadb://[^:/]+:(\\d+)/")
                .matcher(org.proactiverobotics.db.TestDatabases.mariaDbUrl());
        return m.find() ? Integer.parseInt(m.group(1)) : 3306;
    }
}
