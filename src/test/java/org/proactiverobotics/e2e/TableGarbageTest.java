package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import javax.sql.DataSource;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.tables.EngineComments;

/**
 * Garbage written straight into the shared tables during a mission (issue 7): SQL
 * metacharacters, NaN and overflowing numbers, unicode, strings at the column's limit. Commands
 * the robot cannot parse are ignored (it keeps its last valid command); requests for sensors
 * that do not exist and strategy rows for slots that do not exist are ignored by both sides; the
 * mission is accomplished and every table is intact afterwards. On H2 and on MariaDB.
 */
class TableGarbageTest {

    static final String SQL = "'; DROP TABLE checkpoints; --";
    static final List<String> GARBAGE_COMMANDS = List.of(SQL, "DRIVE NaN NaN", "FORWARD 1e999", "STOP; DELETE FROM engine_comments",
            "\u0412\u041f\u0415\u0420\u0401\u0414 0.3 \u2603", "x".repeat(255), "", "TURN_LEFT -0.2", "DRIVE 0.1 0.1 0.1",
            "RECHARGE' OR '1'='1");
    /** Sensor names the robot does not know; the column holds 16 characters. */
    static final List<String> GARBAGE_SENSORS = List.of("gps", "GPS ", " DS", "'; DROP TABLE --", "\u2603\u2603", "NaN", "", "battery", "Odometry");

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void garbageCommandsAreIgnoredTheRobotKeepsItsLastCommandAndTheMissionIsAccomplished(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            Set<Long> injected = ConcurrentHashMap.newKeySet();
            AtomicLong garbageRows = new AtomicLong();
            // After the engine's command of every 61st iteration, a garbage row: the newest when the robot reads.
            java.util.function.UnaryOperator<EngineTables> tables = t -> {
                EngineComments comments = (iteration, simTimeMs, scenario, command) -> {
                    t.comments().send(iteration, simTimeMs, scenario, command);
                    if (iteration % 61 == 0) {
                        String garbage = GARBAGE_COMMANDS.get((int) (garbageRows.getAndIncrement() % GARBAGE_COMMANDS.size()));
                        insert(db.dataSource(), "INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) "
                                + "VALUES (1, ?, ?, ?, ?)", iteration, simTimeMs, "Robert'); DROP TABLE strategy; --", garbage);
                        injected.add(iteration);
                    }
                };
                return new EngineTables(t.readings(), t.requests(), t.mission(), t.strategy(), comments, t.pruneHistory(), t.poses());
            };
            List<String> keptSpeeds = new CopyOnWriteArrayList<>();
            List<String> changedSpeeds = new CopyOnWriteArrayList<>();
            double[] previous = new double[2];
            AtomicLong step = new AtomicLong();
            MissionReport report = Missions.run("reference-arena", db, "safety-first", sim -> {
                long k = step.incrementAndGet(); // the step of engine iteration k
                double left = sim.robot().leftSpeedMps();
                double right = sim.robot().rightSpeedMps();
                if (injected.contains(k)) {
                    (left == previous[0] && right == previous[1] ? keptSpeeds : changedSpeeds).add(k + ": " + left + " " + right);
                }
                previous[0] = left;
                previous[1] = right;
            }, tables).report();

            assertThat(garbageRows.get()).isGreaterThanOrEqualTo(GARBAGE_COMMANDS.size());
            assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
            assertThat(report.collisions()).isZero();
            assertThat(changedSpeeds).as("wheel speeds changed on a garbage command").isEmpty();
            assertThat(keptSpeeds).hasSize(injected.size());
            assertThat(report.commandWins().keySet()).as("the robot executed only the engine's commands")
                    .isSubsetOf("ReachDestination", "ObstacleAvoidance", "BatteryMonitor", "FailSafe", "DecisionMaking");
            assertTablesIntact(db);
            // stored verbatim (prepared statements): the newest garbage rows are still there, as written
            assertThat(count(db, "SELECT COUNT(*) FROM engine_comments WHERE scenario = 'Robert''); DROP TABLE strategy; --'"))
                    .isPositive();
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void garbageRequestsAndStrategyRowsAreIgnoredTheRunIsTheUninterruptedOne(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            AtomicLong step = new AtomicLong();
            AtomicLong strategyRows = new AtomicLong();
            MissionReport report = Missions.run("reference-arena", db, "safety-first", sim -> {
                if (step.incrementAndGet() == 20) {
                    try {
                        strategyRows.set(count(db, "SELECT COUNT(*) FROM strategy WHERE robot_id = 1"));
                    } catch (SQLException e) {
                        throw new IllegalStateException(e);
                    }
                    for (String sensor : GARBAGE_SENSORS) {
                        insert(db.dataSource(), "INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, ?, 0)", sensor);
                    }
                    insert(db.dataSource(), "INSERT INTO strategy (robot_id, slot, scenario, priority, strategy_name, timeout_ms) "
                            + "VALUES (1, ?, ?, ?, ?, ?)", 42, "Nobody'; DROP TABLE strategy; --", Integer.MAX_VALUE, "\u2603", 0L);
                    insert(db.dataSource(), "INSERT INTO strategy (robot_id, slot, scenario, priority, strategy_name, timeout_ms) "
                            + "VALUES (1, ?, ?, ?, ?, ?)", -7, "ObstacleAvoidance", Integer.MIN_VALUE, "'--", Long.MAX_VALUE);
                }
            }).report();

            MissionReport uninterrupted = Missions.onH2("reference-arena").report();
            assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
            assertThat(report.controlSteps()).isEqualTo(uninterrupted.controlSteps());
            assertThat(report.distanceM()).isEqualTo(uninterrupted.distanceM());
            assertThat(report.minClearanceM()).isEqualTo(uninterrupted.minClearanceM());
            assertThat(report.commandWins()).isEqualTo(uninterrupted.commandWins());
            assertThat(report.collisions()).isZero();
            assertTablesIntact(db);
            assertThat(count(db, "SELECT COUNT(*) FROM sensor_requests WHERE robot_id = 1 AND iteration = 0 "
                    + "AND answered_sim_time_ms IS NULL")).as("garbage requests left unanswered").isEqualTo(GARBAGE_SENSORS.size());
            assertThat(count(db, "SELECT COUNT(*) FROM strategy WHERE robot_id = 1")).isEqualTo(strategyRows.get() + 2);
        }
    }

    @Test
    void mariaDbRefusesNonFiniteCheckpointCoordinates() throws Exception {
        Assumptions.assumeTrue(TestDatabases.mariaDbUrl() != null, "MariaDB test skipped: set " + TestDatabases.MARIADB_URL_VARIABLE);
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB)) {
            for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
                assertThatThrownBy(() -> insert(db.dataSource(), "INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m) "
                        + "VALUES (1, 9, ?, 0, 0.25)", bad)).isInstanceOf(IllegalStateException.class);
            }
            assertThat(db.count("checkpoints")).isZero();
        }
    }

    /** Every table of the schema is still there, the mission rows as seeded. */
    private static void assertTablesIntact(TestDatabase db) throws SQLException {
        for (String table : List.of("gps_stored_values", "iudata", "distance_sensor_data", "battery_level", "odometry", "battery_recharged",
                "checkpoints", "engine_comments", "recharge_station", "sensor_requests", "strategy", "engine_state",
                "engine_queue", "rule_failures")) {
            db.count(table); // throws when the table is gone
        }
        assertThat(count(db, "SELECT COUNT(*) FROM checkpoints WHERE robot_id = 1")).isEqualTo(4);
        assertThat(count(db, "SELECT COUNT(*) FROM recharge_station WHERE robot_id = 1")).isEqualTo(1);
        assertThat(count(db, "SELECT COUNT(*) FROM battery_recharged WHERE robot_id = 1")).isEqualTo(1);
    }

    private static long count(TestDatabase db, String sql) throws SQLException {
        try (Connection c = db.dataSource().getConnection(); var s = c.createStatement(); var rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    /** A statement on a connection of its own, committed at once (not the engine's, nor the robot's). */
    static void insert(DataSource dataSource, String sql, Object... values) {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
            c.setAutoCommit(true);
            for (int i = 0; i < values.length; i++) {
                ps.setObject(i + 1, values[i]);
            }
            ps.executeUpdate();
        } catch (SQLException e) {
            throw new IllegalStateException(sql + ": " + e.getMessage(), e);
        }
    }
}
