package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.persistence.JdbcStateStore;
import org.proactiverobotics.engine.persistence.StateCodec;

/** The paper's failsafe: state saved each iteration, resumed on start, a corrupt state refused; on H2 and MariaDB. */
class PersistenceTest {

    private static final StateCodec CODEC = new StateCodec();

    /** Writes what each rule did and the state at each iteration's end as comparable text lines. */
    static final class Recorder implements IterationListener {
        final List<String> lines = new ArrayList<>();
        private final ProactiveEngine[] engine = new ProactiveEngine[1];

        @Override
        public void ruleRan(RuleTrace t) {
            lines.add(t.iteration() + " #" + t.position() + " " + t.rule().name() + " " + t.outcome() + " " + t.partsRun()
                    + (t.failure() == null ? "" : " " + t.failure().message())
                    + " -> " + t.generated().stream().map(Rule::name).toList() + " " + CODEC.ruleJson(t.rule()));
        }

        @Override
        public void iterationEnded(IterationSummary s) {
            ProactiveEngine e = engine[0];
            lines.add(s.iteration() + " end run=" + s.rulesRun() + " gen=" + s.rulesGenerated() + " failed=" + s.rulesFailed()
                    + " memory=" + CODEC.memoryJson(e.memory()) + " next=" + e.nextQueue().stream()
                    .map(r -> CODEC.ruleType(r) + CODEC.ruleJson(r)).collect(Collectors.joining(",")));
        }

        List<String> after(long iteration) {
            return lines.stream().filter(l -> Long.parseLong(l.substring(0, l.indexOf(' '))) > iteration).toList();
        }
    }

    private static ProactiveEngine engine(TestDatabase db, int robotId, Recorder recorder) {
        ProactiveEngine engine = ProactiveEngine.builder().robotId(robotId).algorithm(Algorithm.LAZY)
                .store(new JdbcStateStore(db.dataSource())).listener(recorder).build();
        recorder.engine[0] = engine;
        return engine;
    }

    private static Rule[] firstRules() {
        return new Rule[] {new StartUp(List.of("Gamma", "Beta")), new Workload.Counter("a", 1), new Workload.Counter("b", 2),
            new Workload.FailureCounter()};
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void saveStopResumeGivesTheSameIterationsAsAnEngineThatNeverStopped(DatabaseKind kind) throws Exception {
        int total = 12;
        try (TestDatabase db = TestDatabases.open(kind)) {
            Recorder never = new Recorder();
            ProactiveEngine reference = engine(db, 1, never);
            reference.start(firstRules());
            assertThat(reference.resumed()).isFalse();
            for (int i = 0; i < total; i++) {
                reference.runIteration();
            }
            assertThat(never.lines).anyMatch(l -> l.contains("flaky a")).anyMatch(l -> l.contains("Child"));

            for (int stopAfter : new int[] {2, 3, 9}) {
                int robot = 100 + stopAfter;
                ProactiveEngine first = engine(db, robot, new Recorder());
                first.start(firstRules());
                for (int i = 0; i < stopAfter; i++) {
                    first.runIteration();
                }
                // stop: the engine is dropped; a new one, built the same way, starts from the database
                Recorder resumedLines = new Recorder();
                ProactiveEngine resumed = engine(db, robot, resumedLines);
                resumed.start(new Rule[] {Probe.once("must-be-ignored")});
                assertThat(resumed.resumed()).isTrue();
                assertThat(resumed.iteration()).isEqualTo(stopAfter);
                for (int i = stopAfter; i < total; i++) {
                    resumed.runIteration();
                }
                assertThat(resumedLines.lines).as("resumed after iteration %d", stopAfter)
                        .containsExactlyElementsOf(never.after(stopAfter));
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void theSavedStateIsTheIterationNextQueueAndMemory(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            ProactiveEngine engine = engine(db, 3, new Recorder());
            engine.start(new Workload.Counter("a", 0), new Workload.Flaky("x"), Probe.forever("p"));
            engine.runIteration();
            try (Connection c = db.dataSource().getConnection(); Statement s = c.createStatement()) {
                try (ResultSet rs = s.executeQuery("SELECT iteration, memory_json FROM engine_state WHERE robot_id = 3")) {
                    assertThat(rs.next()).isTrue();
                    assertThat(rs.getLong(1)).isEqualTo(1);
                    assertThat(rs.getString(2)).contains("\"command\":\"C a 1\"");
                }
                List<String> rows = new ArrayList<>();
                try (ResultSet rs = s.executeQuery("SELECT position, rule_type FROM engine_queue WHERE robot_id = 3 ORDER BY position")) {
                    while (rs.next()) {
                        rows.add(rs.getInt(1) + " " + rs.getString(2));
                    }
                }
                assertThat(rows).containsExactly("0 " + Workload.Counter.class.getName(), "1 " + Probe.class.getName());
                try (ResultSet rs = s.executeQuery("SELECT iteration, rule, scenario, part, message FROM rule_failures WHERE robot_id = 3")) {
                    assertThat(rs.next()).isTrue();
                    assertThat(rs.getLong(1) + " " + rs.getString(2) + " " + rs.getString(3) + " " + rs.getString(4) + " "
                            + rs.getString(5)).isEqualTo("1 Flaky flaky ACTIONS IllegalStateException: flaky x");
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aCorruptSavedStateIsRefusedNamingTheRowAndStartingFreshIsExplicit(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            ProactiveEngine engine = engine(db, 7, new Recorder());
            engine.start(Probe.forever("p"), new Workload.Counter("a", 0));
            engine.runIteration();
            engine.runIteration();
            String counter = Workload.Counter.class.getName();
            String row = "engine_queue row (robot_id=7, position=1, rule_type=";

            db.execute("UPDATE engine_queue SET rule_json = '{\"count\": ' WHERE robot_id = 7 AND position = 1");
            assertRefused(db, row + counter + "): corrupt rule_json");
            db.execute("UPDATE engine_queue SET rule_json = '{\"count\": \"many\"}' WHERE robot_id = 7 AND position = 1");
            assertRefused(db, row + counter + "): corrupt rule_json");
            db.execute("UPDATE engine_queue SET rule_type = 'org.example.GoneRule' WHERE robot_id = 7 AND position = 1");
            assertRefused(db, row + "org.example.GoneRule): unknown rule type: no class org.example.GoneRule on the class path");
            db.execute("UPDATE engine_queue SET rule_type = 'java.lang.String' WHERE robot_id = 7 AND position = 1");
            assertRefused(db, row + "java.lang.String): unknown rule type: java.lang.String is not a subclass of " + Rule.class.getName());
            db.execute("UPDATE engine_queue SET position = 5 WHERE robot_id = 7 AND position = 1");
            assertRefused(db, "engine_queue row (robot_id=7, position=2, rule_type=" + Workload.Flaky.class.getName()
                    + "): expected position 1 (positions run 0..n-1 without gaps)");
            db.execute("UPDATE engine_state SET memory_json = '[1, 2' WHERE robot_id = 7");
            assertRefused(db, "engine_state row (robot_id=7, iteration=2): corrupt memory_json");
            db.execute("DELETE FROM engine_state WHERE robot_id = 7");
            assertRefused(db, "engine_queue holds 3 rows for robot_id=7 but engine_state has no row");

            ProactiveEngine fresh = engine(db, 7, new Recorder());
            fresh.startFresh(Probe.once("new"));
            assertThat(fresh.iteration()).isZero();
            assertThat(db.count("engine_queue")).isZero();
            fresh.runIteration();
            ProactiveEngine again = engine(db, 7, new Recorder());
            again.start();
            assertThat(again.resumed()).isTrue();
            assertThat(again.iteration()).isEqualTo(1);
            assertThat(again.nextQueue()).isEmpty();
        }
    }

    private static void assertRefused(TestDatabase db, String message) {
        ProactiveEngine engine = engine(db, 7, new Recorder());
        assertThatThrownBy(() -> engine.start(Probe.once("never")))
                .isInstanceOf(CorruptStateException.class)
                .hasMessageStartingWith(message);
        assertThatThrownBy(engine::runIteration).as("nothing started").isInstanceOf(IllegalStateException.class);
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aFailedSaveKeepsThePreviousStateWhole(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            ProactiveEngine engine = engine(db, 9, new Recorder());
            engine.start(Probe.forever("p"), new Workload.Counter("a", 0));
            engine.runIteration();
            Rule unsaveable = new Rule() { // anonymous: Gson could not load it back, so saving refuses it
                @Override
                public String scenario() {
                    return "test";
                }
            };
            // Submitted while the iteration runs, it joins nextQueue unchecked (a generated one fails its generator instead).
            engine.submit(new Rule() {
                @Override
                public String scenario() {
                    return "test";
                }

                @Override
                protected void actions(RuleContext ctx) {
                    engine.submit(unsaveable);
                }
            });
            assertThatThrownBy(engine::runIteration).isInstanceOf(StateStoreException.class)
                    .hasMessageContaining("cannot be saved: make it a top-level or static nested class");
            SavedState saved = new JdbcStateStore(db.dataSource()).load(9).orElseThrow();
            assertThat(saved.iteration()).isEqualTo(1);
            assertThat(saved.nextQueue()).extracting(Rule::name).containsExactly("p", "Counter-a");
            assertThat(((Workload.Counter) saved.nextQueue().get(1)).count).isEqualTo(1);
        }
    }
}
