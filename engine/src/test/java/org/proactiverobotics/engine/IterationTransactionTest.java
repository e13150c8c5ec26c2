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
import org.proactiverobotics.engine.persistence.IterationTransaction;
import org.proactiverobotics.engine.persistence.JdbcStateStore;
import org.proactiverobotics.engine.persistence.StateCodec;

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
            org.assertj.core.api.Assertions.assertThatThrownBy(tx::commit).as("the caller learns nothing was committed")
                    .isInstanceOf(SQLException.class);
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

    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void withMultiStatementsTheTransactionCostsNoRoundTripOfItsOwnAndStillHoldsEverything(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             com.zaxxer.hikari.HikariDataSource pool = org.proactiverobotics.db.Databases.multiStatementPool(db.jdbcUrl(),
                     db.user(), db.password())) {
            java.util.List<String> sent = new java.util.concurrent.CopyOnWriteArrayList<>();
            IterationTransaction tx = new IterationTransaction(org.proactiverobotics.db.RecordingDataSource.of(pool, sent));
            tx.begin(); // the first finds out what the server takes
            tx.commit();
            sent.clear();

            tx.begin();
            try (PreparedStatement ps = tx.readConnection().prepareStatement("SELECT COUNT(*) FROM engine_comments")) {
                ps.executeQuery().close();
            }
            assertThat(tx.sendNow(INSERT, 1, (ps, p) -> ps.setString(p, "STOP"))).isEqualTo(1);
            tx.writes().add(INSERT, 1, (ps, p) -> ps.setString(p, "RECHARGE"));
            assertThat(db.count("engine_comments")).as("another connection sees nothing yet").isZero();
            tx.commit();
            assertThat(db.count("engine_comments")).isEqualTo(2);
            assertThat(sent).as("the read, the write that opens the transaction, the kept write with COMMIT; no set autocommit")
                    .hasSize(3);
            assertThat(sent.get(1)).startsWith("START TRANSACTION");
            assertThat(sent.get(2)).endsWith("COMMIT");

            sent.clear();
            tx.begin();
            tx.writes().add(INSERT, 1, (ps, p) -> ps.setString(p, "KEPT"));
            tx.commit();
            assertThat(sent).as("kept writes alone open and commit in one round trip").hasSize(1);
            assertThat(sent.get(0)).startsWith("START TRANSACTION").endsWith("COMMIT");
            assertThat(db.count("engine_comments")).isEqualTo(3);

            for (boolean viaConnection : new boolean[] {false, true}) {
                tx.begin();
                if (viaConnection) {
                    insertCommand(tx, "LOST"); // connection() opens the transaction first: nothing escapes it
                } else {
                    tx.sendNow(INSERT, 1, (ps, p) -> ps.setString(p, "LOST"));
                }
                tx.writes().add(INSERT, 1, (ps, p) -> ps.setString(p, "LOST TOO"));
                tx.rollback();
                assertThat(db.count("engine_comments")).as("a rolled-back iteration leaves nothing").isEqualTo(3);
                tx.begin();
                try (java.sql.Statement st = tx.readConnection().createStatement();
                     java.sql.ResultSet rs = st.executeQuery("SELECT @@in_transaction, @@autocommit")) {
                    rs.next();
                    assertThat(rs.getInt(1)).as("and no transaction left open on the pooled connection").isZero();
                    assertThat(rs.getInt(2)).isOne();
                }
                tx.commit();
            }

            tx.begin();
            tx.sendNow(INSERT, 1, (ps, p) -> ps.setString(p, "HALF"));
            tx.writes().add("INSERT INTO no_such_table VALUES (1)", 0, (ps, p) -> { });
            org.assertj.core.api.Assertions.assertThatThrownBy(tx::commit).isInstanceOf(SQLException.class);
            assertThat(db.count("engine_comments")).as("a failed commit leaves nothing").isEqualTo(3);
        }
    }

    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void anIterationChosenAsADeadlocksVictimCommitsNothingAndNoLaterWriteEscapes(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             com.zaxxer.hikari.HikariDataSource pool = org.proactiverobotics.db.Databases.multiStatementPool(db.jdbcUrl(),
                     db.user(), db.password());
             Connection other = db.dataSource().getConnection()) {
            db.execute("INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m) VALUES (1, 1, 0, 0, 1), (1, 2, 0, 0, 1)");
            IterationTransaction tx = new IterationTransaction(pool);
            tx.begin(); // the first finds out what the server takes
            tx.commit();

            tx.begin();
            String mark = "UPDATE checkpoints SET reached = TRUE WHERE robot_id = 1 AND seq = ?";
            tx.sendNow(mark, 1, (ps, p) -> ps.setInt(p, 1)); // opens the transaction, locks checkpoint 1
            other.setAutoCommit(false);
            try (java.sql.Statement st = other.createStatement()) {
                // the other transaction is the heavier one: InnoDB chooses the iteration as the victim
                for (int k = 0; k < 40; k++) {
                    st.executeUpdate("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command)"
                            + " VALUES (2, " + k + ", 0, 'T', 'STOP')");
                }
                st.executeUpdate("UPDATE checkpoints SET unreachable = TRUE WHERE robot_id = 1 AND seq = 2");
            }
            java.util.concurrent.CompletableFuture<Integer> blocked = java.util.concurrent.CompletableFuture.supplyAsync(() -> {
                try (java.sql.Statement st = other.createStatement()) {
                    return st.executeUpdate("UPDATE checkpoints SET unreachable = TRUE WHERE robot_id = 1 AND seq = 1");
                } catch (SQLException e) {
                    throw new IllegalStateException(e);
                }
            });
            Thread.sleep(300); // the other transaction now waits for checkpoint 1
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> tx.sendNow(mark, 1, (ps, p) -> ps.setInt(p, 2)))
                    .isInstanceOf(SQLException.class).extracting(e -> ((SQLException) e).getErrorCode()).isEqualTo(1213);
            assertThat(blocked.get(10, java.util.concurrent.TimeUnit.SECONDS)).isOne();
            other.commit();

            insertCommand(tx, "AFTER THE DEADLOCK"); // a later write of the same iteration ...
            tx.writes().add(INSERT, 1, (ps, p) -> ps.setString(p, "KEPT"));
            org.assertj.core.api.Assertions.assertThatThrownBy(tx::commit).isInstanceOf(SQLException.class);
            assertThat(db.count("engine_comments")).as("... is rolled back with it: only the other's 40 rows").isEqualTo(40);
            try (java.sql.Statement st = other.createStatement();
                 java.sql.ResultSet rs = st.executeQuery("SELECT COUNT(*) FROM checkpoints WHERE reached = TRUE")) {
                rs.next();
                assertThat(rs.getInt(1)).isZero();
            }
        }
    }

    /**
     * A failover URL (as for a Galera cluster) lets the driver replace a lost connection under the
     * same Connection with a new one, in auto-commit: after the loss, nothing of the iteration may
     * commit, neither what it wrote before nor what it writes after. The URL names the test server
     * twice, so that the driver reconnects to it.
     */
    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void anIterationWhoseConnectionAFailoverDriverReplacedCommitsNothing(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("jdbc:mariadb://([^/?]+)(/.*)").matcher(db.jdbcUrl());
            assertThat(m.matches()).as(db.jdbcUrl()).isTrue();
            String failover = "jdbc:mariadb:sequential://" + m.group(1) + "," + m.group(1) + m.group(2);
            try (com.zaxxer.hikari.HikariDataSource pool = org.proactiverobotics.db.Databases.multiStatementPool(failover,
                    db.user(), db.password()); Connection admin = db.dataSource().getConnection()) {
                IterationTransaction tx = new IterationTransaction(pool);
                tx.begin(); // the first finds out what the server takes
                tx.commit();

                tx.begin();
                insertCommand(tx, "BEFORE THE LOSS");
                long id;
                try (java.sql.Statement st = tx.readConnection().createStatement();
                     java.sql.ResultSet rs = st.executeQuery("SELECT CONNECTION_ID()")) {
                    rs.next();
                    id = rs.getLong(1);
                }
                try (java.sql.Statement st = admin.createStatement()) {
                    st.execute("KILL CONNECTION " + id);
                }
                SQLException lost = org.assertj.core.api.Assertions.catchThrowableOfType(SQLException.class, () -> {
                    try (java.sql.Statement st = tx.readConnection().createStatement()) {
                        st.executeQuery("SELECT COUNT(*) FROM engine_comments").close();
                    }
                });
                assertThat((Object) lost).as("the driver reports the reconnection").isNotNull();
                tx.statementFailed(lost); // as the engine's tables do with every failed statement
                insertCommand(tx, "AFTER THE LOSS"); // runs: the driver is connected again
                tx.writes().add(INSERT, 1, (ps, p) -> ps.setString(p, "KEPT"));
                org.assertj.core.api.Assertions.assertThatThrownBy(tx::commit).isInstanceOf(SQLException.class);
                assertThat(db.count("engine_comments")).as("nothing of the iteration, before or after the loss").isZero();

                tx.begin(); // and the next iteration runs as usual
                insertCommand(tx, "NEXT");
                tx.commit();
                assertThat(db.count("engine_comments")).isOne();

                // a connection error the server sent without dropping the connection (Galera's 1047,
                // 08S01, on a node not ready yet): the reopened transaction must not commit what it held
                tx.begin();
                insertCommand(tx, "HELD");
                tx.statementFailed(new SQLException("WSREP has not yet prepared node for application use", "08S01", 1047));
                insertCommand(tx, "AFTER THE ERROR");
                org.assertj.core.api.Assertions.assertThatThrownBy(tx::commit).isInstanceOf(SQLException.class);
                assertThat(db.count("engine_comments")).as("neither the held write nor the later one").isOne();
            }
        }
    }

    private static final String INSERT =
            "INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (1, 1, 0, 'T', ?)";
}
