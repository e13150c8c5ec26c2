package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Scenario plug-ins from outside, through the command line: a jar compiled against the engine
 * alone runs in {@code run}; its suggestions win exactly when the strategy file ranks them
 * highest; a plug-in failing in every part leaves the robot safe and the failures recorded; and
 * every bad plug-in or strategy file is refused with exit 2, naming it, writing nothing.
 */
class PluginCommandTest extends CommandLineTest {

    /** A 1.5 m hop with no obstacle, and a short time limit for the runs that never arrive. */
    static final String HOP = """
            {"name": "plugin-hop", "maxSimTimeS": 20, "arena": {"radiusM": 3.0},
             "robot": {"x": 0.0, "y": -1.0, "headingDeg": 90.0},
             "checkpoints": [{"x": 0.0, "y": 0.5}], "rechargeStation": {"x": -2.0, "y": 0.0, "radiusM": 0.35}}
            """;

    @TempDir
    static Path shared;
    static Path slowpoke;
    static Path broken;
    static Path world;

    @TempDir
    Path tmp;

    @BeforeAll
    static void buildPlugins() throws IOException {
        slowpoke = PluginJars.slowpoke(shared);
        broken = PluginJars.broken(shared);
        world = Files.writeString(shared.resolve("plugin-hop.json"), HOP);
    }

    private Path strategy(String name, String json) throws IOException {
        return Files.writeString(tmp.resolve(name), json);
    }

    private JsonObject report(Path out) throws IOException {
        return JsonParser.parseString(Files.readString(out.resolve("report.json"))).getAsJsonObject();
    }

    private List<JsonObject> trace(Path out) throws IOException {
        return Files.readAllLines(out.resolve("trace.jsonl")).stream().map(l -> JsonParser.parseString(l).getAsJsonObject()).toList();
    }

    @Test
    void aPluginRankedFirstWinsEveryDecisionItSuggestsInAndRankedLastNone() throws Exception {
        Path first = tmp.resolve("first");
        Path top = strategy("top.json", "{\"name\": \"slow-first\", \"priorities\": {\"Slowpoke\": 9, \"ObstacleAvoidance\": 3,"
                + " \"BatteryMonitor\": 2, \"ReachDestination\": 1}}");
        assertThat(run("run", "--world", world.toString(), "--scenarios", slowpoke.toString(), "--strategy-file", top.toString(),
                "--quiet", "--out", first.toString())).as(err.toString()).isZero();
        assertThat(out.toString()).contains("strategy slow-first, plug-in scenarios Slowpoke");
        JsonObject firstReport = report(first);
        assertThat(firstReport.get("strategy").getAsString()).isEqualTo("slow-first");
        long slowWins = firstReport.getAsJsonObject("commandWins").get("Slowpoke").getAsLong();
        assertThat(slowWins).isPositive();
        for (JsonObject t : trace(first)) {
            boolean suggested = t.getAsJsonObject("suggestions").has("Slowpoke");
            assertThat(t.get("winner").getAsString().equals("Slowpoke")).as(t.toString()).isEqualTo(suggested);
        }

        Path last = tmp.resolve("last");
        Path bottom = strategy("bottom.json", "{\"priorities\": {\"ObstacleAvoidance\": 3, \"BatteryMonitor\": 2,"
                + " \"ReachDestination\": 1, \"Slowpoke\": 0}}");
        assertThat(run("run", "--world", world.toString(), "--scenarios", slowpoke.toString(), "--strategy-file",
                bottom.toString(), "--quiet", "--out", last.toString())).as(err.toString()).isZero();
        assertThat(report(last).getAsJsonObject("commandWins").has("Slowpoke")).isFalse();
        assertThat(trace(last)).anySatisfy(t -> assertThat(t.getAsJsonObject("suggestions").has("Slowpoke")).isTrue());
        // ranked first it drives at a quarter of a metre a second: the hop takes longer than ReachDestination's
        assertThat(firstReport.get("simTimeS").getAsDouble()).isGreaterThan(report(last).get("simTimeS").getAsDouble());
    }

    @Test
    void aStrategyThatLeavesAPluginOutRanksItBelowEveryListedOneAndSaysSo() throws Exception {
        Path out = tmp.resolve("named");
        assertThat(run("run", "--world", world.toString(), "--scenarios", slowpoke.toString(), "--quiet", "--out",
                out.toString())).as(err.toString()).isZero();
        assertThat(err.toString()).contains("strategy safety-first leaves out Slowpoke: ranked below every scenario it lists");
        assertThat(report(out).getAsJsonObject("commandWins").has("Slowpoke")).isFalse();
    }

    @Test
    void aPluginFailingInEveryPartLeavesTheRobotStoppedAndTheFailuresRecorded() throws Exception {
        Path out = tmp.resolve("broken");
        Path db = tmp.resolve("db");
        String url = "jdbc:h2:file:" + db.resolve("p") + ";MODE=MySQL;DATABASE_TO_LOWER=TRUE";
        StringBuilder priorities = new StringBuilder("{\"priorities\": {");
        for (String s : List.of("FailsGuardData", "FailsGuards", "FailsConditionData", "FailsConditions", "FailsActions",
                "FailsGeneration", "FailsToStart")) {
            priorities.append('"').append(s).append("\": 9, ");
        }
        priorities.append("\"ObstacleAvoidance\": 3, \"BatteryMonitor\": 2, \"ReachDestination\": 1}}");
        Path top = strategy("broken-first.json", priorities.toString());
        int code = run("run", "--world", world.toString(), "--scenarios", broken.toString(), "--strategy-file", top.toString(),
                "--db", url, "--db-user", "sa", "--db-password", "", "--quiet", "--out", out.toString());
        assertThat(code).as(err.toString()).isEqualTo(1);
        JsonObject report = report(out);
        assertThat(report.get("outcome").getAsString()).isEqualTo("TIME_LIMIT");
        assertThat(report.get("collisions").getAsInt()).isZero();
        assertThat(report.get("distanceM").getAsDouble()).as("the fail-safe's STOP stood in, ranked first").isLessThan(0.05);
        assertThat(report.get("ruleFailures").getAsLong()).isPositive();
        try (Connection c = DriverManager.getConnection(url, "sa", "");
             Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT scenario, COUNT(*) FROM rule_failures GROUP BY scenario ORDER BY scenario")) {
            java.util.Set<String> failed = new java.util.TreeSet<>();
            while (rs.next()) {
                failed.add(rs.getString(1));
            }
            assertThat(failed).contains("FailsGuardData", "FailsGuards", "FailsConditionData", "FailsConditions",
                    "FailsActions", "FailsGeneration", "FailsToStart");
        }
    }

    @Test
    void underSafetyFirstABrokenPluginRankedLastChangesNothingForTheMission() throws Exception {
        Path with = tmp.resolve("with");
        assertThat(run("run", "--world", "reference-arena", "--scenarios", broken.toString(), "--link", "direct", "--quiet",
                "--out", with.toString())).as(err.toString()).isZero();
        Path without = tmp.resolve("without");
        assertThat(run("run", "--world", "reference-arena", "--link", "direct", "--quiet", "--out", without.toString())).isZero();
        JsonObject a = report(with);
        JsonObject b = report(without);
        for (String key : List.of("outcome", "checkpointsReached", "simTimeS", "distanceM", "collisions", "minBattery")) {
            assertThat(a.get(key)).as(key).isEqualTo(b.get(key));
        }
    }

    // ---------------------------------------------------------------- refused

    private void assertRefused(String reason, String... args) {
        Path out = tmp.resolve("never");
        List<String> all = new java.util.ArrayList<>(List.of(args));
        if (args[0].equals("run")) {
            all.addAll(List.of("--quiet", "--link", "direct", "--out", out.toString()));
        }
        err.getBuffer().setLength(0);
        assertThat(run(all.toArray(String[]::new))).as(err.toString()).isEqualTo(2);
        assertThat(err.toString()).contains(reason).doesNotContain("\tat ").doesNotContain("Caused by");
        assertThat(out).doesNotExist();
    }

    @Test
    void badPluginsAreRefusedNamingThePathTheClassOrTheScenario() throws Exception {
        Path missing = tmp.resolve("missing.jar");
        assertRefused("missing.jar: no such file or folder", "run", "--scenarios", missing.toString());
        Path fake = Files.writeString(tmp.resolve("fake.jar"), "not a zip");
        assertRefused("fake.jar: not a jar", "run", "--scenarios", fake.toString());
        Path emptyFolder = Files.createDirectories(tmp.resolve("empty"));
        assertRefused("empty: folder holds no .jar file", "run", "--scenarios", emptyFolder.toString());
        Path noServices = PluginJars.build(tmp.resolve("noservices.jar"), Map.of("x.Lone",
                PluginJars.bare("x", "Lone", "Lone")), null);
        assertRefused("noservices.jar: holds no scenario", "run", "--scenarios", noServices.toString());
        Path unknownClass = PluginJars.build(tmp.resolve("unknown.jar"), Map.of(), List.of("com.example.Missing"));
        assertRefused("com.example.Missing", "run", "--scenarios", unknownClass.toString());
        Path throwing = PluginJars.build(tmp.resolve("throwing.jar"), Map.of("t.Throwing", """
                package t;
                public final class Throwing implements org.proactiverobotics.engine.Scenario {
                    public Throwing() { throw new IllegalStateException("constructor says no"); }
                    public String name() { return "Throwing"; }
                }
                """), List.of("t.Throwing"));
        assertRefused("constructor says no", "run", "--scenarios", throwing.toString());
        Path builtInName = PluginJars.build(tmp.resolve("impostor.jar"), Map.of("i.Impostor",
                PluginJars.bare("i", "Impostor", "ObstacleAvoidance")), List.of("i.Impostor"));
        assertRefused("impostor.jar: scenario 'ObstacleAvoidance' (i.Impostor) has the name of a built-in scenario",
                "run", "--scenarios", builtInName.toString());
        Path twinA = PluginJars.build(tmp.resolve("twin-a.jar"), Map.of("a.Twin", PluginJars.bare("a", "Twin", "Twin")),
                List.of("a.Twin"));
        Path twinB = PluginJars.build(tmp.resolve("twin-b.jar"), Map.of("b.Twin", PluginJars.bare("b", "Twin", "Twin")),
                List.of("b.Twin"));
        assertRefused("two scenarios are named 'Twin': a.Twin in", "run", "--scenarios", twinA + "," + twinB);
        Path copy = Files.copy(twinA, tmp.resolve("copy-of-twin-a.jar"));
        assertRefused("copy-of-twin-a.jar: its scenario class a.Twin is already loaded from " + twinA
                + " (a class is loaded once: give each plug-in jar once)", "run", "--scenarios", twinA + "," + copy);
        Path badName = PluginJars.build(tmp.resolve("badname.jar"), Map.of("n.Spaced",
                PluginJars.bare("n", "Spaced", "has space")), List.of("n.Spaced"));
        assertRefused("is named 'has space'", "run", "--scenarios", badName.toString());
        assertRefused("missing.jar: no such file or folder", "engine", "--db", "jdbc:h2:mem:x", "--scenarios", missing.toString());
    }

    @Test
    void badStrategyFilesAreRefusedNamingTheFileAndTheKey() throws Exception {
        Path notJson = strategy("broken.json", "{\"priorities\": ");
        assertRefused("broken.json: not valid JSON", "run", "--strategy-file", notJson.toString());
        Path unknown = strategy("unknown.json", "{\"priorities\": {\"Nobody\": 3}}");
        assertRefused("unknown.json: strategy unknown names scenario 'Nobody', which is not loaded", "run",
                "--strategy-file", unknown.toString());
        Path fraction = strategy("fraction.json", "{\"priorities\": {\"Slowpoke\": 1.5}}");
        assertRefused("fraction.json: priorities.Slowpoke must be an integer", "run", "--scenarios", slowpoke.toString(),
                "--strategy-file", fraction.toString());
        assertRefused("give --strategy or --strategy-file, not both", "run", "--strategy", "safety-first",
                "--strategy-file", unknown.toString());
        assertRefused("unknown.json: strategy unknown names scenario 'Nobody'", "engine", "--db", "jdbc:h2:mem:x",
                "--strategy-file", unknown.toString());
    }
}
