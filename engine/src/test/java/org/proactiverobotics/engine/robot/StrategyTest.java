package org.proactiverobotics.engine.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.engine.tables.StrategyTable;

/** Strategies as data: bundled files, user files, their checks, and the PriorityArray rows they give. */
class StrategyTest {

    private static final Map<String, Integer> SLOTS = RobotEngine.freshSlots(ScenarioPlugins.none());

    @Test
    void theBundledStrategiesRankTheBuiltInScenarios() {
        assertThat(Strategy.names()).containsExactly("safety-first", "destination-first", "battery-first");
        assertThat(SLOTS).containsExactly(Map.entry("ReachDestination", 0), Map.entry("BatteryMonitor", 1),
                Map.entry("ObstacleAvoidance", 2));
        assertThat(rows("safety-first")).containsExactly("0 ReachDestination 1", "1 BatteryMonitor 2", "2 ObstacleAvoidance 3");
        assertThat(rows("destination-first")).containsExactly("0 ReachDestination 3", "1 BatteryMonitor 1", "2 ObstacleAvoidance 2");
        assertThat(rows("battery-first")).containsExactly("0 ReachDestination 1", "1 BatteryMonitor 3", "2 ObstacleAvoidance 2");
    }

    private static List<String> rows(String name) {
        return Strategy.named(name).rows(SLOTS).stream().map(e -> e.slot() + " " + e.scenario() + " " + e.priority()).toList();
    }

    @Test
    void aFileNamesScenariosAndALeftOutOneRanksBelowEveryListedOne(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("careful.json");
        Files.writeString(file, "{\"priorities\": {\"Plugin\": 10, \"ObstacleAvoidance\": 5, \"ReachDestination\": -2},"
                + " \"timeoutsMs\": {\"Plugin\": 500}}");
        Strategy s = Strategy.read(file);
        assertThat(s.name()).isEqualTo("careful");
        Map<String, Integer> slots = new LinkedHashMap<>(SLOTS);
        slots.put("Plugin", 3);
        assertThat(s.unlisted(slots)).containsExactly("BatteryMonitor");
        List<StrategyTable.Entry> rows = s.rows(slots);
        assertThat(rows).extracting(e -> e.scenario() + "=" + e.priority() + "/" + e.timeoutMs())
                .containsExactly("ReachDestination=-2/0", "BatteryMonitor=-3/0", "ObstacleAvoidance=5/0", "Plugin=10/500");
        assertThat(Strategy.of(rows).priorities()).containsEntry("Plugin", 10).containsEntry("BatteryMonitor", -3);
    }

    @Test
    void badFilesAreRefusedNamingTheFileAndTheKey(@TempDir Path dir) throws Exception {
        assertRefused(dir, "{\"priorities\": {\"ObstacleAvoidance\": 1,}", "not valid JSON");
        assertRefused(dir, "[1, 2]", "must be a JSON object");
        assertRefused(dir, "{\"priorities\": {\"ObstacleAvoidance\": 2.5}}", "priorities.ObstacleAvoidance must be an integer");
        assertRefused(dir, "{\"priorities\": {\"ObstacleAvoidance\": \"high\"}}", "priorities.ObstacleAvoidance must be an integer");
        assertRefused(dir, "{\"priorities\": {\"ObstacleAvoidance\": 1e12}}", "priorities.ObstacleAvoidance must be between");
        assertRefused(dir, "{\"priorities\": {}}", "priorities must be an object with at least one");
        assertRefused(dir, "{\"name\": \"x\"}", "priorities must be an object");
        assertRefused(dir, "{\"priorities\": {\"A\": 1}, \"timeouts\": {}}", "unknown key 'timeouts'");
        assertRefused(dir, "{\"priorities\": {\"A\": 1}, \"timeoutsMs\": {\"A\": -5}}", "timeoutsMs.A must be between 0");
        assertRefused(dir, "{\"name\": \"bad name!\", \"priorities\": {\"A\": 1}}", "strategy name 'bad name!'");
        assertThatThrownBy(() -> Strategy.read(dir.resolve("missing.json"))).isInstanceOf(StrategyException.class)
                .hasMessageContaining("missing.json").hasMessageContaining("cannot be read");
    }

    private static void assertRefused(Path dir, String json, String reason) throws Exception {
        Path file = Files.writeString(dir.resolve("s.json"), json);
        assertThatThrownBy(() -> Strategy.read(file)).as(json).isInstanceOf(StrategyException.class)
                .hasMessageContaining(file.toString()).hasMessageContaining(reason);
    }

    @Test
    void aScenarioThatIsNotLoadedOrDoesNotSuggestIsRefusedNamingTheLoadedOnes() {
        Strategy s = Strategy.parse("{\"priorities\": {\"Speedy\": 3, \"ReachDestination\": 1}}", "speedy.json");
        assertThatThrownBy(() -> s.rows(SLOTS)).isInstanceOf(StrategyException.class)
                .hasMessageContaining("'Speedy'").hasMessageContaining("ReachDestination, BatteryMonitor, ObstacleAvoidance");
        Strategy dataAcquisition = Strategy.parse("{\"priorities\": {\"DataAcquisition\": 3}}", "da.json");
        assertThatThrownBy(() -> dataAcquisition.check(SLOTS)).hasMessageContaining("does not suggest");
        assertThatThrownBy(() -> Strategy.named("yolo")).hasMessageContaining("known: safety-first");
        assertThat(Strategy.named("Safety-First")).as("a bundled name in any case").isEqualTo(Strategy.named("safety-first"));
    }
}
