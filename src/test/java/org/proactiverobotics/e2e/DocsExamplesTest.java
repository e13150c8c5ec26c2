package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.fail;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.google.gson.JsonStreamParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.robot.StrategyException;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldValidationException;

/**
 * Every {@code ```json} block of docs/*.md and README.md is checked against the real thing: a world file
 * by the real parser, a report.json or a trace.jsonl line against the files a real mission writes, a
 * strategy file by the real strategy parser and against the built-in scenarios' slots. A block that is
 * none of these fails, so the manual cannot carry unchecked JSON.
 */
class DocsExamplesTest extends CommandLineTest {

    /** Precedes a world-file example that must be refused. */
    static final String INVALID_WORLD = "<!-- invalid-world -->";
    private static final Pattern JSON_BLOCK = Pattern.compile("(?m)^```json\\n(.*?)^```", Pattern.DOTALL);

    /** What the robot process's report leaves out: its database user may read neither table, nor see the engine's belief. */
    private static final Set<String> ENGINE_ONLY_REPORT_KEYS = Set.of("strategy", "ruleFailures", "poseError");
    /** The fields a trace.jsonl line has only when there is something to say (schemaVersion 3). */
    private static final Set<String> OPTIONAL_TRACE_KEYS = Set.of("belief", "route", "mapDelta", "reason", "robot");
    /** The keys a report of a world with several robots adds to the one-robot report's. */
    private static final Set<String> FLEET_REPORT_KEYS = Set.of("robotCollisions", "robots");

    private static JsonObject realReport;
    private static JsonObject realTraceLine;

    /** A short real mission, on the embedded database: the files every example is compared with. */
    @BeforeAll
    static void runAShortMission(@TempDir Path dir) throws IOException {
        Path world = dir.resolve("short-hop.json");
        Files.writeString(world, TwoProcessMissionTest.SHORT_HOP);
        Path out = dir.resolve("out");
        DocsExamplesTest cli = new DocsExamplesTest();
        assertThat(cli.run("run", "--quiet", "--world", world.toString(), "--out", out.toString()))
                .as(cli.err.toString()).isZero();
        realReport = JsonParser.parseString(Files.readString(out.resolve("report.json"))).getAsJsonObject();
        realTraceLine = JsonParser.parseString(Files.readAllLines(out.resolve("trace.jsonl")).get(0)).getAsJsonObject();
    }

    /** One JSON value of a block, where it was found and whether it is marked as a bad world. */
    record Example(String where, JsonElement value, boolean markedInvalidWorld) {
    }

    static List<Example> examples() throws IOException {
        Path root = Deployment.root();
        List<Path> files = new ArrayList<>();
        files.add(root.resolve("README.md"));
        try (Stream<Path> docs = Files.list(root.resolve("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(files::add);
        }
        List<Example> examples = new ArrayList<>();
        for (Path file : files) {
            String text = Files.readString(file);
            Matcher m = JSON_BLOCK.matcher(text);
            while (m.find()) {
                String where = root.relativize(file) + ":" + (text.substring(0, m.start()).split("\n", -1).length);
                boolean invalid = text.substring(0, m.start()).stripTrailing().endsWith(INVALID_WORLD);
                try {
                    JsonStreamParser values = new JsonStreamParser(m.group(1));
                    while (values.hasNext()) {
                        examples.add(new Example(where, values.next(), invalid));
                    }
                } catch (RuntimeException e) {
                    fail(where + ": a ```json block that is not JSON: " + e.getMessage());
                }
            }
        }
        return examples;
    }

    @Test
    void everyJsonBlockOfTheDocsIsARecognisedAndCheckedExample() throws IOException {
        List<Example> examples = examples();
        assertThat(examples).as("the manual's JSON examples").hasSizeGreaterThanOrEqualTo(5);
        int worlds = 0;
        int invalidWorlds = 0;
        int reports = 0;
        int traceLines = 0;
        int strategies = 0;
        for (Example e : examples) {
            JsonObject o = e.value().isJsonObject() ? e.value().getAsJsonObject() : null;
            if (e.markedInvalidWorld()) {
                assertThatThrownBy(() -> WorldFiles.parse(e.value().toString(), e.where()))
                        .as(e.where() + ": marked " + INVALID_WORLD + " but the parser accepts it")
                        .isInstanceOf(WorldValidationException.class);
                invalidWorlds++;
            } else if (o != null && (o.has("checkpoints") || o.has("robots")) && o.has("arena")) {
                try {
                    WorldFiles.parse(o.toString(), e.where());
                } catch (WorldValidationException ex) {
                    fail(e.where() + ": a world example the parser refuses (mark it " + INVALID_WORLD
                            + " if that is the point): " + ex.problems());
                }
                worlds++;
            } else if (o != null && o.has("outcome") && o.has("checkpointsReached")) {
                Set<String> expected = new LinkedHashSet<>(realReport.keySet());
                if (!o.has("strategy")) { // the robot process's report (docs/report.md): the engine's fields left out
                    expected.removeAll(ENGINE_ONLY_REPORT_KEYS);
                }
                if (o.has("robots")) { // a world with several robots (docs/report.md)
                    expected.addAll(FLEET_REPORT_KEYS);
                }
                assertThat(o.keySet()).as(e.where() + ": report.json's keys").isEqualTo(expected);
                assertThat(o.getAsJsonObject("timing").keySet()).as(e.where() + ": report.json's timing keys")
                        .isEqualTo(realReport.getAsJsonObject("timing").keySet());
                reports++;
            } else if (o != null && o.has("winner") && o.has("suggestions")) {
                Set<String> beyond = new LinkedHashSet<>(o.keySet());
                beyond.removeAll(realTraceLine.keySet());
                assertThat(o.keySet()).as(e.where() + ": trace.jsonl's keys").containsAll(realTraceLine.keySet());
                assertThat(beyond).as(e.where() + ": trace.jsonl's keys beyond the first line's: the optional ones")
                        .isSubsetOf(OPTIONAL_TRACE_KEYS);
                traceLines++;
            } else if (o != null && o.has("priorities")) {
                checkStrategyFile(e);
                strategies++;
            } else {
                fail(e.where() + ": a JSON example that is neither a world file, a report.json, a trace.jsonl"
                        + " line nor a strategy file, so nothing checks it: " + e.value());
            }
        }
        assertThat(List.of(worlds, invalidWorlds, reports, traceLines, strategies)).as("each kind is shown at least once")
                .doesNotContain(0);
    }

    /**
     * A strategy-file example must be what {@code --strategy-file} accepts on a mission of the built-in
     * scenarios and the example project's plug-ins (examples/scenario-example, which the tutorial builds):
     * parsed by the real parser, naming only scenarios that have a slot, and turned into one strategy row
     * per slot. One named like a bundled strategy must be that strategy.
     *
     * @return the strategy's name
     */
    private static String checkStrategyFile(Example e) {
        Map<String, Integer> builtInSlots = slotsWithExamplePlugins();
        Strategy strategy;
        try {
            strategy = Strategy.parse(e.value().toString(), e.where());
            assertThat(strategy.rows(builtInSlots)).as(e.where() + ": one strategy row per slot")
                    .hasSize(builtInSlots.size());
        } catch (StrategyException ex) {
            throw new AssertionError(e.where() + ": a strategy-file example that --strategy-file refuses: "
                    + ex.getMessage(), ex);
        }
        if (Strategy.names().contains(strategy.name())) {
            assertThat(strategy).as(e.where() + ": an example named like the bundled strategy " + strategy.name())
                    .isEqualTo(Strategy.named(strategy.name()));
        }
        return strategy.name();
    }

    /**
     * The slots of a mission with the example project's scenarios as plug-ins: the built-in ones, then
     * each scenario its services file lists, by the name its class declares.
     */
    static Map<String, Integer> slotsWithExamplePlugins() {
        Path example = Deployment.root().resolve("examples/scenario-example");
        Map<String, Integer> slots = new java.util.LinkedHashMap<>(RobotEngine.freshSlots(ScenarioPlugins.none()));
        Pattern name = Pattern.compile("String NAME = \"([^\"]+)\"");
        try {
            for (String type : Files.readAllLines(example.resolve("src/main/resources/" + PluginJars.SERVICES))) {
                if (type.isBlank()) {
                    continue;
                }
                Matcher m = name.matcher(Files.readString(example.resolve("src/main/java/" + type.trim().replace('.', '/') + ".java")));
                assertThat(m.find()).as(type + " declares its NAME").isTrue();
                slots.put(m.group(1), slots.size());
            }
        } catch (IOException ex) {
            throw new java.io.UncheckedIOException(ex);
        }
        return slots;
    }

    @Test
    void theExampleProjectsStrategyFileIsWhatStrategyFileAccepts() throws IOException {
        Path careful = Deployment.root().resolve("examples/scenario-example/careful.json");
        Example e = new Example("examples/scenario-example/careful.json", JsonParser.parseString(Files.readString(careful)), false);
        assertThat(checkStrategyFile(e)).isEqualTo("careful");
        assertThat(slotsWithExamplePlugins()).containsKeys("SpeedGovernor", "ReturnToStation");
    }

    @Test
    void aStrategyFileExampleThatStrategyFileWouldRefuseFailsTheCheck() {
        assertThat(checkStrategyFile(strategyExample("{\"name\": \"cautious\", \"priorities\": {\"ObstacleAvoidance\": 3,"
                + " \"ReachDestination\": 1}, \"timeoutsMs\": {\"ObstacleAvoidance\": 200}}"))).isEqualTo("cautious");
        assertThatThrownBy(() -> checkStrategyFile(strategyExample("{\"priorities\": {\"SpeedGovenor\": 2}}")))
                .isInstanceOf(AssertionError.class).hasMessageContaining("SpeedGovenor");
        assertThatThrownBy(() -> checkStrategyFile(strategyExample("{\"priorities\": {\"ReachDestination\": \"high\"}}")))
                .isInstanceOf(AssertionError.class).hasMessageContaining("priorities.ReachDestination");
        assertThatThrownBy(() -> checkStrategyFile(strategyExample("{\"priorities\": {\"ReachDestination\": 1}, \"weights\": {}}")))
                .isInstanceOf(AssertionError.class).hasMessageContaining("weights");
        assertThatThrownBy(() -> checkStrategyFile(strategyExample("{\"name\": \"safety-first\", \"priorities\":"
                + " {\"ReachDestination\": 3, \"ObstacleAvoidance\": 2, \"BatteryMonitor\": 1}}")))
                .as("an example named like a bundled strategy but not it").isInstanceOf(AssertionError.class);
    }

    private static Example strategyExample(String json) {
        return new Example("docs/example.md:1", JsonParser.parseString(json), false);
    }

    @Test
    void theRealReportHasTheFieldsTheManualDescribes() throws IOException {
        String manual = Files.readString(Deployment.root().resolve("docs/report.md"));
        for (String key : realReport.keySet()) {
            assertThat(manual).as("docs/report.md describes report.json's " + key).contains("| `" + key + "` |");
        }
        for (String key : realReport.getAsJsonObject("timing").keySet()) {
            assertThat(manual).as("docs/report.md describes timing's " + key).contains("| `" + key + "` |");
        }
        for (String key : realTraceLine.keySet()) {
            assertThat(manual).as("docs/report.md describes trace.jsonl's " + key).contains("| `" + key + "` |");
        }
        for (String key : OPTIONAL_TRACE_KEYS) {
            assertThat(manual).as("docs/report.md describes trace.jsonl's optional " + key).contains("| `" + key + "` |");
        }
    }
}
