package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The robot process SIGKILLed mid-mission (two checkpoints behind it) and started again with
 * the same flags, the engine process running throughout.
 *
 * <p>What "the mission is accomplished" means here: the simulator's state lived in the killed
 * process, so the new robot process is a new robot run from the world's start pose (a real
 * robot would have been carried back). The mission rows are not seeded again (the checkpoints,
 * station and recharge level stay as they are, one row each); the engine sees the new run,
 * resets its own rows (commands, requests, reached marks) and starts its scenarios afresh; the
 * new run is then the uninterrupted run, step for step, and accomplishes the mission.
 */
@Tag("reliability")
class RobotRestartReliabilityTest {

    private static final String WORLD = "reference-arena";

    @TempDir
    Path tmp;

    @Test
    void aRobotKilledMidMissionAndStartedAgainRunsTheMissionAgainWithoutReseedingIt() throws Exception {
        Uninterrupted reference = Uninterrupted.of(WORLD);
        try (Deployment deployment = Deployment.create(); Clocks clocks = new Clocks(deployment.adminUrl(), 1)) {
            Path engineLog = tmp.resolve("engine.log");
            Process engine = deployment.start("engine", Map.of(), engineLog);
            Map<String, String> robotOptions = new LinkedHashMap<>();
            robotOptions.put("--out", tmp.resolve("out").toString());
            Path firstLog = tmp.resolve("robot-1.log");
            Process robot = deployment.start("robot", robotOptions, firstLog);
            clocks.await("two checkpoints reached", clocks::reached, n -> n >= 2, robot, 120);
            long firstRun = clocks.robotRun();
            String missionRows = missionRows(deployment);

            robot.toHandle().destroyForcibly(); // SIGKILL
            assertThat(robot.waitFor(10, TimeUnit.SECONDS)).isTrue();
            assertThat(robot.exitValue()).isEqualTo(137);
            Thread.sleep(300);
            long served = clocks.engineStep();
            Thread.sleep(500);
            assertThat(clocks.engineStep()).as("the engine serves nothing while the robot is away").isEqualTo(served);
            assertThat(engine.isAlive()).isTrue();
            assertThat(tmp.resolve("out/report.json")).doesNotExist();

            Path secondLog = tmp.resolve("robot-2.log");
            robot = deployment.start("robot", robotOptions, secondLog);
            assertThat(robot.waitFor(180, TimeUnit.SECONDS)).as("robot finished").isTrue();
            String second = Files.readString(secondLog);
            assertThat(robot.exitValue()).as(second).isZero();
            assertThat(clocks.robotRun()).isGreaterThan(firstRun);

            JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out/report.json"))).getAsJsonObject();
            TwoProcessMissionTest.assertSameGroundTruth(report, reference.report());
            assertThat(report.get("outcome").getAsString()).isEqualTo("MISSION_ACCOMPLISHED");
            assertThat(report.get("collisions").getAsInt()).isZero();
            assertThat(clocks.checkpoints()).isEqualTo(reference.checkpoints());
            EngineCrashReliabilityTest.assertMarkedOnceInOrder(clocks.checkpoints());
            assertThat(missionRows(deployment)).as("mission rows, not seeded again").isEqualTo(missionRows);
            assertThat(second).contains("already in the database; left as they are").doesNotContain("Exception");

            engine.destroy();
            assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
            assertThat(engine.exitValue()).isZero();
            String engineText = Files.readString(engineLog);
            assertThat(engineText.split("new robot run", -1)).as(engineText).hasSize(3); // two runs
            assertThat(engineText).doesNotContain("Exception");
        }
    }

    /** The mission rows the robot seeds, as text: checkpoints (without the engine's marks), station, recharge level. */
    private static String missionRows(Deployment deployment) throws Exception {
        return deployment.queryLong("SELECT COUNT(*) FROM checkpoints WHERE robot_id = 1") + " checkpoints, "
                + deployment.queryLong("SELECT ROUND(SUM(x_m * 1000 + y_m * 10 + radius_m)) FROM checkpoints WHERE robot_id = 1")
                + " checksum; " + deployment.queryLong("SELECT COUNT(*) FROM recharge_station WHERE robot_id = 1") + " station, "
                + deployment.queryLong("SELECT COUNT(*) FROM battery_recharged WHERE robot_id = 1") + " recharge level; "
                + deployment.queryLong("SELECT COUNT(*) FROM strategy WHERE robot_id = 1") + " strategy rows";
    }
}
