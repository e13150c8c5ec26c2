package org.proactiverobotics.engine.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.sql.DataSource;
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
            assertThat(engine.scenarios()).containsExactly("DataAcquisition", "Localisation", "Mapping", "BatteryMonitor", "ReachDestination",
                    "Alpha", "ObstacleAvoidance", "FailSafe", "DecisionMaking");
            engine.startFresh();
            assertThat(engine.slots()).containsExactly(Map.entry("ReachDestination", 0), Map.entry("BatteryMonitor", 1),
                    Map.entry("ObstacleAvoidance", 2), Map.entry("Alpha", 3));
            assertThat(RobotEngine.freshSlots(ScenarioPlugins.of(new Alpha()))).isEqualTo(Map.of("ReachDestination", 0,
                    "BatteryMonitor", 1, "ObstacleAvoidance", 2, "Alpha", 3));
        }
    }

    @Test
    void theStartOrderIsTheBuildersAndItsPhraseIsTheJavadocs() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Schema.apply(db.dataSource());
            RobotEngine engine = RobotEngine.builder().database(db.dataSource())
                    .plugins(ScenarioPlugins.of(new Alpha())).build();
            assertThat(engine.scenarios()).isEqualTo(RobotEngine.startOrder(List.of("Alpha")));
        }
        assertThat(RobotEngine.startOrderPhrase()).isEqualTo(RobotEngine.ORDER_TEXT).isEqualTo("DataAcquisition → Localisation → Mapping"
                + " → BatteryMonitor → ReachDestination → plug-ins → ObstacleAvoidance → FailSafe → DecisionMaking");
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

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void snapshotsReadAheadInOneQueryGiveEachRobotTheIterationsItsOwnReadsGive(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             HikariDataSource pool = Databases.multiStatementPool(db.jdbcUrl(), db.user(), db.password())) {
            Schema.apply(pool);
            List<String> sent = new CopyOnWriteArrayList<>();
            DataSource recording = RecordingDataSource.of(pool, sent);
            // robots 11-13 read ahead together; 21-23, the same rows each, read their own
            List<RobotEngine> ahead = new ArrayList<>();
            List<RobotEngine> own = new ArrayList<>();
            for (int r = 1; r <= 3; r++) {
                for (int robot : new int[] {10 + r, 20 + r}) {
                    db.execute("INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m) VALUES (" + robot + ", 1, "
                            + (2.0 + r) + ", 1.0, 0.3), (" + robot + ", 2, 0.5, " + (0.5 * r) + ", 0.3)");
                    db.execute("INSERT INTO battery_recharged (robot_id, level_pct) VALUES (" + robot + ", 95)");
                    RobotEngine engine = RobotEngine.builder().robotId(robot).database(robot < 20 ? recording : pool).build();
                    engine.startFresh();
                    engine.writeStrategy(Strategy.named(Strategy.SAFETY_FIRST));
                    (robot < 20 ? ahead : own).add(engine);
                }
            }
            for (int k = 1; k <= 8; k++) {
                for (int r = 1; r <= 3; r++) {
                    for (int robot : new int[] {10 + r, 20 + r}) { // the robots sense: the same readings for both of a pair
                        long t = 32L * k;
                        db.execute("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (" + robot + ", " + t
                                + ", " + (0.1 * k) + ", " + (0.2 * r) + ")");
                        db.execute("INSERT INTO iudata (robot_id, sim_time_ms, roll_rad, pitch_rad, yaw_rad) VALUES (" + robot
                                + ", " + t + ", 0, 0, " + (0.05 * k * r) + ")");
                        db.execute("INSERT INTO battery_level (robot_id, sim_time_ms, level_pct) VALUES (" + robot + ", " + t
                                + ", " + (100 - k) + ")");
                        db.execute("INSERT INTO distance_sensor_data (robot_id, sim_time_ms, sensor_index, angle_rad, distance_m,"
                                + " range_m) VALUES (" + robot + ", " + t + ", 0, -0.5, " + (2.0 - 0.1 * r) + ", 2), (" + robot
                                + ", " + t + ", 1, 0, " + (1.5 - 0.1 * k) + ", 2), (" + robot + ", " + t + ", 2, 0.5, 2, 2)");
                        db.execute("UPDATE sensor_requests SET answered_sim_time_ms = " + t + " WHERE robot_id = " + robot);
                    }
                }
                sent.clear();
                try (IterationBatch batch = IterationBatch.start(recording, ahead)) {
                    assertThat(batch.batched()).as("a batch (not on H2)").isEqualTo(kind != DatabaseKind.H2);
                    for (int i = 0; i < 3; i++) {
                        ahead.get(i).iterate();
                        own.get(i).iterate();
                    }
                    if (kind != DatabaseKind.H2) {
                        assertThat(savedIteration(pool, 11)).as("nothing of the batch in the database before its commit").isEqualTo(k - 1);
                        assertThat(savedIteration(pool, 21)).isEqualTo(k);
                    }
                    batch.commit();
                }
                assertThat(savedIteration(pool, 11)).isEqualTo(k);
                List<String> reads = sent.stream().filter(x -> x.contains("FROM gps_stored_values")).toList();
                List<String> commits = sent.stream().filter(x -> x.endsWith("COMMIT") || x.equals("commit")).toList();
                if (kind == DatabaseKind.H2) {
                    assertThat(reads).as("H2: each reads its own").noneMatch(x -> x.contains("SELECT 21 AS k")); // the second robot's first kind
                    assertThat(commits).as("H2: each commits its own").hasSize(3);
                } else {
                    assertThat(reads).as("iteration %d: one read for the three robots", k).hasSize(1);
                    assertThat(reads.get(0)).contains("SELECT 41 AS k"); // the third robot's first kind
                    assertThat(commits).as("iteration %d: one commit for the three robots", k).hasSize(1);
                    assertThat(commits.get(0)).contains("robot_id, iteration, memory_json");
                }
            }
            for (int r = 1; r <= 3; r++) {
                assertThat(rows(pool, "SELECT iteration, scenario, command FROM engine_comments WHERE robot_id = ? ORDER BY id", 10 + r))
                        .as("robot %d's commands", 10 + r).isNotEmpty()
                        .isEqualTo(rows(pool, "SELECT iteration, scenario, command FROM engine_comments WHERE robot_id = ? ORDER BY id", 20 + r));
                assertThat(rows(pool, "SELECT sensor, iteration FROM sensor_requests WHERE robot_id = ? ORDER BY id", 10 + r))
                        .isEqualTo(rows(pool, "SELECT sensor, iteration FROM sensor_requests WHERE robot_id = ? ORDER BY id", 20 + r));
                assertThat(rows(pool, "SELECT iteration, memory_json FROM engine_state WHERE robot_id = ?", 10 + r))
                        .isEqualTo(rows(pool, "SELECT iteration, memory_json FROM engine_state WHERE robot_id = ?", 20 + r));
            }

            // A snapshot read ahead and dropped is never used: the next iteration reads the rows as they are then.
            RobotEngine.readAhead(recording, ahead.subList(0, 2));
            ahead.get(0).dropReadAhead();
            ahead.get(1).dropReadAhead();
            db.execute("UPDATE checkpoints SET x_m = 9, y_m = 9 WHERE robot_id = 11 AND seq = 1");
            sent.clear();
            ahead.get(0).iterate();
            assertThat(sent.stream().filter(x -> x.contains("FROM gps_stored_values"))).as("its own read").hasSize(1);
        }
    }

    @Test
    void whenAnIterationOrTheCommitOfABatchFailsThoseRunInItRollBackAndEachEngineGoesOnFromItsSavedState() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB);
             HikariDataSource pool = Databases.multiStatementPool(db.jdbcUrl(), db.user(), db.password())) {
            Schema.apply(pool);
            boolean[] refuse = {false};
            boolean[] badWrite = {false};
            List<RobotEngine> engines = new ArrayList<>();
            for (int robot = 31; robot <= 33; robot++) {
                RobotEngine.Builder builder = RobotEngine.builder().robotId(robot).database(pool);
                if (robot == 32) { // a lease lost, for instance: the check in the iteration's transaction throws
                    builder.guard((c, n) -> {
                        if (refuse[0]) {
                            throw new SQLException("robot 32 refused");
                        }
                    });
                }
                RobotEngine engine = builder.build();
                engine.startFresh();
                engines.add(engine);
            }
            long[] expected = {0, 0, 0};
            for (int k = 1; k <= 5; k++) {
                refuse[0] = k == 3; // robot 32's iteration fails: 31, run before it, rolls back with it; 33 commits alone
                badWrite[0] = k == 4; // the batch's one round trip fails: all three roll back
                List<RobotEngine> rolledBack;
                try (IterationBatch batch = IterationBatch.start(pool, engines)) {
                    assertThat(batch.batched()).isTrue();
                    for (RobotEngine engine : engines) {
                        try {
                            engine.iterate((writes, n) -> {
                                if (badWrite[0] && engine == engines.get(0)) {
                                    writes.add("UPDATE no_such_table SET x = 1", 0, (ps, p) -> { });
                                }
                            });
                        } catch (StateStoreException e) {
                            assertThat(e.getMessage()).contains("robot 32 refused");
                        }
                    }
                    try {
                        batch.commit();
                        assertThat(k).as("batch %d committed", k).isNotIn(3, 4);
                    } catch (SQLException e) {
                        assertThat(k).as("batch %d rolled back: %s", k, e.getMessage()).isIn(3, 4);
                    }
                    rolledBack = batch.rolledBack();
                }
                for (int i = 0; i < 3; i++) {
                    boolean committed = k == 3 ? i == 2 : k != 4;
                    expected[i] += committed ? 1 : 0;
                    assertThat(savedIteration(pool, 31 + i)).as("robot %d after batch %d", 31 + i, k).isEqualTo(expected[i]);
                }
                assertThat(rolledBack).as("batch %d: returned, but not committed", k)
                        .containsExactlyElementsOf(k == 3 ? List.of(engines.get(0)) : k == 4 ? engines : List.of());
            }
            assertThat(engines.stream().map(e -> e.engine().iteration()))
                    .as("each resumed from its saved state, then went on").containsExactly(expected[0], expected[1], expected[2]);
            assertThat(expected).containsExactly(3, 3, 4);
        }
    }

    private static long savedIteration(DataSource pool, int robot) throws Exception {
        try (Connection c = pool.getConnection(); PreparedStatement ps = c.prepareStatement(
                "SELECT iteration FROM engine_state WHERE robot_id = ?")) {
            ps.setInt(1, robot);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? rs.getLong(1) : 0;
            }
        }
    }

    private static List<List<String>> rows(DataSource pool, String sql, int robot) throws Exception {
        List<List<String>> rows = new ArrayList<>();
        try (Connection c = pool.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
            ps.setInt(1, robot);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    List<String> row = new ArrayList<>();
                    for (int i = 1; i <= rs.getMetaData().getColumnCount(); i++) {
                        row.add(rs.getString(i));
                    }
                    rows.add(row);
                }
            }
        }
        return rows;
    }

    private static List<Long> clockAndState(DataSource pool) throws Exception {
        try (Connection c = pool.getConnection(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(
                "SELECT step, iteration, (SELECT iteration FROM engine_state WHERE robot_id = 6) FROM engine_clock WHERE robot_id = 6")) {
            assertThat(rs.next()).isTrue();
            return List.of(rs.getLong(1), rs.getLong(2), rs.getLong(3));
        }
    }
}
