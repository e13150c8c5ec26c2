package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
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
 * A plug-in in the paper's deployment: the engine process loads it (--scenarios, --strategy-file)
 * and the two processes, on MariaDB as the least-privilege users, give the one-process run's
 * ground truth; a third process changes the strategy from a file, by scenario name.
 */
class PluginTwoProcessTest {

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

        String shown = strategy(0, "5");
        assertThat(shown).contains("strategy slow-first").contains("Slowpoke");
        Path bottom = Files.writeString(tmp.resolve("bottom.json"), "{\"priorities\": {\"ReachDestination\": 5, \"Slowpoke\": 1}}");
        assertThat(strategy(0, "5", "--set-file", bottom.toString())).contains("slow-first -> bottom")
                .contains("leaves out BatteryMonitor, ObstacleAvoidance");
        assertThat(deployment.queryLong("SELECT priority FROM strategy WHERE robot_id = 5 AND scenario = 'Slowpoke'")).isEqualTo(1);
        assertThat(deployment.queryLong("SELECT slot FROM strategy WHERE robot_id = 5 AND scenario = 'Slowpoke'")).isEqualTo(3);
        Path stranger = Files.writeString(tmp.resolve("stranger.json"), "{\"priorities\": {\"Stranger\": 5}}");
        assertThat(strategy(2, "5", "--set-file", stranger.toString())).contains("stranger.json")
                .contains("'Stranger', which is not loaded").contains("Slowpoke");

        engine.destroy();
        assertThat(engine.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(engine.exitValue()).as(Files.readString(engineLog)).isZero();
    }

    private static String strategy(int expectedCode, String robotId, String... more) {
        StringWriter out = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(out, true));
        List<String> args = new java.util.ArrayList<>(List.of("strategy", "--db", deployment.url(), "--db-user",
                deployment.engineUser, "--db-password=" + Deployment.ENGINE_PASSWORD, "--robot-id", robotId));
        args.addAll(List.of(more));
        assertThat(cl.execute(args.toArray(String[]::new))).as(out.toString()).isEqualTo(expectedCode);
        return out.toString();
    }
}
