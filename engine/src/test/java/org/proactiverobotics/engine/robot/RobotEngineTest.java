package org.proactiverobotics.engine.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.RecordingDataSource;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.engine.StateStoreException;
import org.proactiverobotics.engine.testscenarios.Alpha;

/** The one wiring: start order, slots, and plug-ins that are also on the class path. */
class RobotEngineTest {

    @Test
    void pluginsStartAfterTheBuiltInsThatFindTheWayAndBeforeTheCollisionMonitorFailSafeAndTheDecision() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Schema.apply(db.dataSource());
            RobotEngine engine = RobotEngine.builder().database(db.dataSource()).plugins(ScenarioPlugins.of(new Alpha())).build();
            assertThat(engine.scenarios()).containsExactly("DataAcquisition", "Mapping", "BatteryMonitor", "ReachDestination",
                    "Alpha", "ObstacleAvoidance", "FailSafe", "DecisionMaking");
            engine.startFresh();
            assertThat(engine.slots()).containsExactly(Map.entry("ReachDestination", 0), Map.entry("BatteryMonitor", 1),
                    Map.entry("ObstacleAvoidance", 2), Map.entry("Alpha", 3));
            assertThat(RobotEngine.freshSlots(ScenarioPlugins.of(new Alpha()))).isEqualTo(Map.of("ReachDestination", 0,
                    "BatteryMonitor", 1, "ObstacleAvoidance", 2, "Alpha", 3));
        }
    }

    @Test
    void aPluginAlsoListedOnTheClassPathIsTakenOnceAsThePlugin() throws Exception {
        // Alpha is in this module's test META-INF/services, as a user's scenario is in their own project's tests.
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Schema.apply(db.dataSource());
            Alpha given = new Alpha();
            RobotEngine engine = RobotEngine.builder().database(db.dataSource()).plugins(ScenarioPlugins.of(given)).build();
            assertThat(engine.registry().get("Alpha")).isSameAs(given);
        }
    }

    @Test
    void onlyStartsTheNamedScenariosInTheStandardOrderAndRefusesAnUnknownOne() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Schema.apply(db.dataSource());
            RobotEngine engine = RobotEngine.builder().database(db.dataSource())
                    .only("DecisionMaking", "ObstacleAvoidance").build();
            assertThat(engine.scenarios()).containsExactly("ObstacleAvoidance", "DecisionMaking");
            assertThatThrownBy(() -> RobotEngine.builder().database(db.dataSource()).only("Nope").build())
                    .hasMessageContaining("unknown scenario 'Nope'");
            assertThatThrownBy(() -> ScenarioPlugins.of(new Alpha(), new Alpha())).isInstanceOf(PluginException.class)
                    .hasMessageContaining("'Alpha'");
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void onMariaDbAnIterationsWritesGoWithItsCommitInOneRoundTrip(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             HikariDataSource pool = Databases.multiStatementPool(db.jdbcUrl(), db.user(), db.password())) {
            Schema.apply(pool);
            List<String> sent = new CopyOnWriteArrayList<>();
            RobotEngine engine = RobotEngine.builder().robotId(5).database(RecordingDataSource.of(pool, sent)).build();
            engine.startFresh();
            engine.iterate(); // the first finds out what the server takes
            sent.clear();
            engine.iterate();
            List<String> statements = sent.stream().filter(x -> !List.of("commit", "rollback", "setAutoCommit").contains(x)).toList();
            if (kind == DatabaseKind.MARIADB) {
                assertThat(statements.size()).as("at most the snapshot, then the writes with COMMIT").isBetween(1, 2);
                assertThat(statements.get(statements.size() - 1)).contains("engine_state", "engine_queue").endsWith("COMMIT");
                assertThat(sent).as("no transaction control of its own (set autocommit, commit)")
                        .doesNotContain("setAutoCommit", "commit", "rollback");
                assertThat(statements.subList(0, statements.size() - 1)).allMatch(x -> x.startsWith("SELECT"));
            } else {
                assertThat(statements.size()).as("H2: a statement each").isGreaterThanOrEqualTo(2);
                assertThat(statements).noneMatch(x -> x.contains("COMMIT"));
            }
            try (Connection c = pool.getConnection(); Statement s = c.createStatement();
                 ResultSet rs = s.executeQuery("SELECT iteration, (SELECT COUNT(*) FROM engine_queue WHERE robot_id = 5)"
                         + " FROM engine_state WHERE robot_id = 5")) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getLong(1)).as("the second iteration saved").isEqualTo(2);
                assertThat(rs.getLong(2)).isPositive();
            }
            RobotEngine resumed = RobotEngine.builder().robotId(5).database(pool).build();
            assertThat(resumed.resume()).isTrue();
            assertThat(resumed.engine().iteration()).isEqualTo(2);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void rowsGivenToAnIterationCommitWithItOrNotAtAll(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             HikariDataSource pool = Databases.multiStatementPool(db.jdbcUrl(), db.user(), db.password())) {
            Schema.apply(pool);
            db.execute("INSERT INTO engine_clock (robot_id, run_id, step, iteration) VALUES (6, 1, 0, 0)");
            RobotEngine engine = RobotEngine.builder().robotId(6).database(pool).build();
            engine.startFresh();
            for (int k = 1; k <= 2; k++) {
                engine.iterate((writes, n) -> writes.add("UPDATE engine_clock SET step = ?, iteration = ? WHERE robot_id = 6", 2,
                        (ps, p) -> {
                            ps.setLong(p, 10 * n);
                            ps.setLong(p + 1, n);
                        }));
            }
            assertThat(clockAndState(pool)).as("step, iteration served; iteration saved").containsExactly(20L, 2L, 2L);

            assertThatThrownBy(() -> engine.iterate((writes, n) -> writes.add("UPDATE no_such_table SET x = 1", 0, (ps, p) -> { })))
                    .isInstanceOf(StateStoreException.class);
            assertThat(clockAndState(pool)).as("the iteration whose rows failed left nothing").containsExactly(20L, 2L, 2L);
            engine.iterate();
            assertThat(clockAndState(pool)).as("and its engine goes on from the saved state").containsExactly(20L, 2L, 3L);
        }
    }

    private static List<Long> clockAndState(javax.sql.DataSource pool) throws Exception {
        try (Connection c = pool.getConnection(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(
                "SELECT step, iteration, (SELECT iteration FROM engine_state WHERE robot_id = 6) FROM engine_clock WHERE robot_id = 6")) {
            assertThat(rs.next()).isTrue();
            return List.of(rs.getLong(1), rs.getLong(2), rs.getLong(3));
        }
    }
}
