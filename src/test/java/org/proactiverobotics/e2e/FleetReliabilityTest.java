package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.mission.MissionReport;

/**
 * A fleet on one MariaDB: three robot processes, one engine process serving all three
 * ({@code --robot-ids}), a second engine standing by for them ({@code --standby-ids}), each serving
 * its robots on one thread, so that their iterations run as batches (one read, one commit). The first
 * engine is SIGKILLed mid-mission; once the robots' leases expire the second takes them over,
 * resumes each from its saved state, and every robot ends with the ground truth of the
 * uninterrupted one-process run; the lease rows end with the standby's name and a bumped epoch.
 * (That an engine which lost a lease commits nothing: EngineLeaseTest.) About a minute: in the
 * reliability profile.
 */
@Tag("reliability")
class FleetReliabilityTest {

    private static final int ROBOTS = 3;

    @TempDir
    Path tmp;

    @Test
    void aStandbyEngineTakesOverTheFleetOfAKilledEngineAndEveryRobotEndsAsIfUninterrupted() throws Exception {
        MissionReport reference = Missions.onH2("reference-arena").report();
        try (Deployment deployment = Deployment.create()) {
            Path logA = tmp.resolve("engine-a.log");
            Path logB = tmp.resolve("engine-b.log");
            Process engineA = deployment.start("engine", engine("1-" + ROBOTS, null, "engine-a"), logA);
            Process engineB = deployment.start("engine", engine("99", "1-" + ROBOTS, "engine-b"), logB);
            Deployment.awaitLog(logB, "waiting for the robot", 60);

            List<Process> robots = new ArrayList<>();
            for (int id = 1; id <= ROBOTS; id++) {
                Map<String, String> options = new LinkedHashMap<>();
                options.put("--robot-id", String.valueOf(id));
                options.put("--out", tmp.resolve("out-" + id).toString());
                robots.add(deployment.start("robot", options, tmp.resolve("robot-" + id + ".log")));
            }
            // engine A serves all three for a while, then dies without a word
            awaitAllServedBeyond(deployment, 300, 90);
            engineA.toHandle().destroyForcibly();
            assertThat(engineA.waitFor(10, TimeUnit.SECONDS)).isTrue();
            long[] servedAtKill = served(deployment);

            for (int id = 1; id <= ROBOTS; id++) {
                Process robot = robots.get(id - 1);
                Path robotLog = tmp.resolve("robot-" + id + ".log");
                assertThat(robot.waitFor(180, TimeUnit.SECONDS)).as("robot %d finished", id).isTrue();
                assertThat(robot.exitValue()).as(Files.readString(robotLog)).isZero();
                JsonObject report = JsonParser.parseString(Files.readString(tmp.resolve("out-" + id + "/report.json")))
                        .getAsJsonObject();
                TwoProcessMissionTest.assertSameGroundTruth(report, reference);
            }
            engineB.destroy();
            assertThat(engineB.waitFor(30, TimeUnit.SECONDS)).isTrue();
            assertThat(engineB.exitValue()).isZero();

            String a = Files.readString(logA);
            String b = Files.readString(logB);
            assertThat(a).contains("lease of robot 1 taken").contains("new robot run").doesNotContain("Exception");
            assertThat(b).contains("lease of robot 1 taken").contains("lease of robot 2 taken")
                    .contains("lease of robot 3 taken").contains("resuming robot run").doesNotContain("new robot run")
                    .containsPattern("robots [0-9,-]+: \\d+ of their \\d+ iterations run in [1-9]\\d* batches").doesNotContain("Exception");
            try (Connection c = DriverManager.getConnection(deployment.adminUrl()); Statement s = c.createStatement();
                 ResultSet rs = s.executeQuery("SELECT robot_id, owner, epoch FROM engine_lease ORDER BY robot_id")) {
                for (int id = 1; id <= ROBOTS; id++) {
                    assertThat(rs.next()).isTrue();
                    assertThat(rs.getInt(1)).isEqualTo(id);
                    assertThat(rs.getString(2)).isEqualTo("engine-b");
                    assertThat(rs.getLong(3)).as("taken by A, then by B").isEqualTo(2);
                }
            }
            for (int id = 1; id <= ROBOTS; id++) {
                assertThat(deployment.queryLong("SELECT iteration FROM engine_state WHERE robot_id = " + id))
                        .isEqualTo(reference.controlSteps());
                assertThat(servedAtKill[id - 1]).as("robot %d was part-way when A died", id)
                        .isBetween(300L, reference.controlSteps() - 1);
            }
            System.out.printf("fleet of %d robots, engine A killed at steps %d/%d/%d, engine B finished them%n", ROBOTS,
                    servedAtKill[0], servedAtKill[1], servedAtKill[2]);
        }
    }

    private static Map<String, String> engine(String ids, String standby, String name) {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("--robot-id", null); // the compose command's option, dropped below
        options.put("--robot-ids", ids);
        if (standby != null) {
            options.put("--standby-ids", standby);
        }
        options.put("--engine-name", name);
        options.put("--threads", "1"); // its robots on one thread: their iterations run, and are killed, as batches
        options.put("--lease-s", "2");
        options.put("--log-every", "250");
        return options;
    }

    private static long[] served(Deployment deployment) throws Exception {
        long[] steps = new long[ROBOTS];
        for (int id = 1; id <= ROBOTS; id++) {
            try (Connection c = DriverManager.getConnection(deployment.adminUrl()); Statement s = c.createStatement();
                 ResultSet rs = s.executeQuery("SELECT step FROM engine_clock WHERE robot_id = " + id)) {
                steps[id - 1] = rs.next() ? rs.getLong(1) : -1;
            }
        }
        return steps;
    }

    private static void awaitAllServedBeyond(Deployment deployment, long step, long timeoutS) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutS);
        while (System.nanoTime() < deadline) {
            long[] steps = served(deployment);
            if (java.util.Arrays.stream(steps).allMatch(s -> s >= step)) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("the robots were not all served beyond step " + step + " within " + timeoutS + " s");
    }
}
