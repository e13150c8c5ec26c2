package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;

/** One transaction per iteration: all of an iteration's writes commit together, or none. */
class IterationTransactionTest {

    /** As the engine's tables do: on the iteration's connection when one is open, else on a pooled one. */
    private static void insertCommand(IterationTransaction tx, String command) throws SQLException {
        Connection inIteration = tx.connection();
        try (Connection own = inIteration == null ? tx.getConnection() : null) {
            Connection c = inIteration != null ? inIteration : own;
            try (PreparedStatement ps = c.prepareStatement(
                    "INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (1, 1, 0, 'T', ?)")) {
                ps.setString(1, command);
                ps.executeUpdate();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void writesOfAnIterationAreSeenByOthersOnlyOnceItCommits(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            IterationTransaction tx = new IterationTransaction(db.dataSource());
            tx.begin();
            insertCommand(tx, "STOP");
            insertCommand(tx, "RECHARGE");
            assertThat(db.count("engine_comments")).as("another connection sees nothing yet").isZero();
            tx.commit();
            assertThat(db.count("engine_comments")).isEqualTo(2);
            insertCommand(tx, "STOP"); // outside an iteration: a plain, auto-committed connection
            assertThat(db.count("engine_comments")).isEqualTo(3);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aPartThatRollsBackItsOwnUnitDiscardsTheWholeIteration(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            IterationTransaction tx = new IterationTransaction(db.dataSource());
            tx.begin();
            insertCommand(tx, "STOP");
            tx.markRollbackOnly(); // as JdbcStateStore does on a failed save
            tx.commit();
            assertThat(db.count("engine_comments")).isZero();
            tx.begin();
            insertCommand(tx, "STOP");
            tx.rollback();
            assertThat(db.count("engine_comments")).isZero();
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aStateStoreOverARolledBackIterationSavesEveryRowAgain(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            IterationTransaction tx = new IterationTransaction(db.dataSource());
            JdbcStateStore store = new JdbcStateStore(tx);
            ProactiveEngine engine = ProactiveEngine.builder().robotId(1).store(store).build();
            engine.startFresh(new Workload.Counter("a", 0), new Workload.Counter("b", 1));
            tx.begin();
            engine.runIteration();
            tx.commit();
            tx.begin();
            engine.runIteration(); // the counters change: their rows are rewritten ...
            tx.rollback();         // ... but that iteration never reaches the database
            tx.begin();
            engine.runIteration();
            tx.commit();
            ProactiveEngine resumed = ProactiveEngine.builder().robotId(1).store(new JdbcStateStore(db.dataSource())).build();
            resumed.start();
            assertThat(resumed.iteration()).isEqualTo(3);
            StateCodec codec = new StateCodec();
            assertThat(resumed.nextQueue()).extracting(codec::ruleJson)
                    .containsExactlyElementsOf(engine.nextQueue().stream().map(codec::ruleJson).toList());
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void otherThreadsDoNotJoinTheIteration(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            IterationTransaction tx = new IterationTransaction(db.dataSource());
            tx.begin();
            AtomicBoolean plain = new AtomicBoolean();
            Thread other = new Thread(() -> {
                try (Connection c = tx.getConnection()) {
                    plain.set(tx.connection() == null && c.getAutoCommit());
                } catch (SQLException e) {
                    throw new IllegalStateException(e);
                }
            });
            other.start();
            other.join();
            assertThat(tx.connection()).as("the iteration's own thread gets its connection").isNotNull();
            tx.rollback();
            assertThat(plain).isTrue();
        }
    }
}
