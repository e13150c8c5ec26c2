package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.persistence.JdbcStateStore;
import org.proactiverobotics.engine.persistence.StateCodec;

/** Slots are the engine's: given at start, entered by RuleContext.suggest, saved with the memory, kept on a resume. */
class SlotsTest {

    /** Suggests its text every iteration, in the name of its scenario. */
    static final class Suggester extends Rule {
        String scenario;
        String command;

        private Suggester() {
        }

        Suggester(String scenario, String command) {
            this.scenario = scenario;
            this.command = command;
        }

        @Override
        public String scenario() {
            return scenario;
        }

        @Override
        protected void actions(RuleContext ctx) {
            ctx.suggest(command);
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }

    private static ProactiveEngine.Builder builder() {
        return ProactiveEngine.builder().slot("A", 0).slot("B", 1).slot("C", 2).slot("Plugin");
    }

    @Test
    void aSuggestionGoesToTheSlotTheEngineGaveItsScenario() {
        ProactiveEngine engine = builder().build();
        engine.start(new Suggester("B", "FORWARD 0.1"), new Suggester("Plugin", "STOP"));
        engine.runIteration();
        CommandArray commands = engine.memory().commandArray();
        assertThat(engine.memory().slots()).containsExactly(Map.entry("A", 0), Map.entry("B", 1), Map.entry("C", 2),
                Map.entry("Plugin", 3));
        assertThat(commands.get(1).command()).isEqualTo("FORWARD 0.1");
        assertThat(commands.get(1).scenario()).isEqualTo("B");
        assertThat(commands.get(3).command()).isEqualTo("STOP");
        assertThat(commands.get(3).iteration()).isEqualTo(1);
    }

    @Test
    void aScenarioWithoutASlotOrAnEmptyCommandFailsTheRuleNotTheEngine() {
        ProactiveEngine engine = builder().build();
        engine.start(new Suggester("NoSlot", "STOP"), new Suggester("A", " "), new Suggester("C", "x".repeat(256)),
                new Suggester("B", "STOP"));
        IterationSummary summary = engine.runIteration();
        assertThat(summary.rulesFailed()).isEqualTo(3);
        assertThat(engine.lastIterationFailures()).extracting(RuleFailure::message)
                .anySatisfy(m -> assertThat(m).contains("'NoSlot'").contains("has no CommandArray slot"))
                .anySatisfy(m -> assertThat(m).contains("not a command"));
        assertThat(engine.memory().commandArray().get(1).command()).isEqualTo("STOP");
    }

    @Test
    void moreScenariosThanTheDefaultEightSlotsGrowTheArrays() {
        ProactiveEngine.Builder b = ProactiveEngine.builder();
        for (int i = 0; i < 12; i++) {
            b.slot("S" + i);
        }
        ProactiveEngine engine = b.build();
        engine.start(new Suggester("S11", "STOP"));
        engine.runIteration();
        assertThat(engine.memory().commandArray().size()).isEqualTo(12);
        assertThat(engine.memory().priorityArray().size()).isEqualTo(12);
        assertThat(engine.memory().commandArray().get(11).command()).isEqualTo("STOP");
    }

    @Test
    void aTakenPreferredSlotGivesTheLowestFreeOne() {
        ProactiveEngine engine = ProactiveEngine.builder().slot("First").slot("Second", 0).slot("Third", 5).build();
        engine.start();
        assertThat(engine.memory().slots()).containsExactly(Map.entry("First", 0), Map.entry("Second", 1),
                Map.entry("Third", 5));
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void savedSlotsWinOnAResumeAndANewScenarioGetsAFreeOne(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            ProactiveEngine first = ProactiveEngine.builder().store(new JdbcStateStore(db.dataSource()))
                    .slot("A").slot("B").build();
            first.startFresh(new Suggester("B", "STOP"));
            first.runIteration();
            // restarted with another plug-in first in line: the saved slots stay, the newcomer gets slot 2
            ProactiveEngine second = ProactiveEngine.builder().store(new JdbcStateStore(db.dataSource()))
                    .slot("New").slot("A").slot("B").build();
            second.start();
            assertThat(second.resumed()).isTrue();
            assertThat(second.memory().slots()).containsExactly(Map.entry("A", 0), Map.entry("B", 1), Map.entry("New", 2));
            second.runIteration();
            assertThat(second.memory().commandArray().get(1).command()).isEqualTo("STOP");
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aStateSavedBeforeSlotsWereSavedResumesWithTheConfiguredSlots(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            ProactiveEngine old = ProactiveEngine.builder().store(new JdbcStateStore(db.dataSource())).build();
            old.startFresh(new Suggester("A", "STOP"), Probe.forever("p"));
            old.runIteration(); // A has no slot here: it fails; p is queued
            // The memory as versions before slots wrote it: no "slots" key.
            try (Connection c = db.dataSource().getConnection();
                 PreparedStatement update = c.prepareStatement("UPDATE engine_state SET memory_json = ? WHERE robot_id = 1")) {
                update.setString(1, "{\"commandArray\":{\"slots\":[null,null,null,null,null,null,null,null]},"
                        + "\"priorityArray\":{\"priorities\":[1,2,3,0,0,0,0,0]},\"values\":{}}");
                assertThat(update.executeUpdate()).isEqualTo(1);
            }
            ProactiveEngine resumed = ProactiveEngine.builder().store(new JdbcStateStore(db.dataSource()))
                    .slot("ReachDestination", 0).slot("BatteryMonitor", 1).slot("ObstacleAvoidance", 2).build();
            resumed.start();
            assertThat(resumed.resumed()).isTrue();
            assertThat(resumed.iteration()).isEqualTo(1);
            assertThat(resumed.memory().slots()).containsExactly(Map.entry("ReachDestination", 0),
                    Map.entry("BatteryMonitor", 1), Map.entry("ObstacleAvoidance", 2));
            assertThat(resumed.memory().priorityArray().get(2)).isEqualTo(3);
            resumed.runIteration();
            try (Connection c = db.dataSource().getConnection();
                 PreparedStatement q = c.prepareStatement("SELECT memory_json FROM engine_state WHERE robot_id = 1");
                 ResultSet rs = q.executeQuery()) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getString(1)).contains("\"slots\":{\"ReachDestination\":0,\"BatteryMonitor\":1,\"ObstacleAvoidance\":2}");
            }
        }
    }

    @Test
    void aCorruptSlotMapIsRefusedNamingIt() {
        StateCodec codec = new StateCodec();
        List<String> corrupt = List.of(
                "{\"commandArray\":{\"slots\":[null]},\"priorityArray\":{\"priorities\":[0]},\"values\":{},\"slots\":{\"A\":-1}}",
                "{\"commandArray\":{\"slots\":[null]},\"priorityArray\":{\"priorities\":[0]},\"values\":{},\"slots\":{\"A\":0,\"B\":0}}");
        for (String json : corrupt) {
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> codec.memory(json))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("corrupt memory_json: slots");
        }
    }
}
