package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** A transaction as one multi-statement round trip: all of it or nothing, and only where the server takes it. */
class RoundTripTest {

    private static RoundTrip twoInserts(int robotId, String secondTable) {
        MultiRow rows = MultiRow.insert("battery_level", "robot_id", "sim_time_ms", "level_pct", "charging");
        RoundTrip trip = new RoundTrip();
        trip.addRows(rows, 4, 2, (ps, p, r) -> {
            ps.setInt(p, robotId);
            ps.setLong(p + 1, 32L * r);
            ps.setDouble(p + 2, 90 - r);
            ps.setBoolean(p + 3, false);
        });
        trip.add("INSERT INTO " + secondTable + " (robot_id, sim_time_ms, x_m, y_m) VALUES (?, ?, ?, ?)", 4, (ps, p) -> {
            ps.setInt(p, robotId);
            ps.setLong(p + 1, 64);
            ps.setDouble(p + 2, 1.25);
            ps.setDouble(p + 3, -2.5e-7);
        });
        return trip;
    }

    private static int inTransaction(Connection c) throws SQLException {
        try (Statement s = c.createStatement(); ResultSet rs = s.executeQuery("SELECT @@in_transaction")) {
            rs.next();
            return rs.getInt(1);
        }
    }

    /** A pool as the robot's: multi-statements allowed. */
    private static HikariDataSource multiStatementPool(TestDatabase db) {
        return new HikariDataSource(Databases.allowMultiStatements(Databases.config(db.jdbcUrl(), db.user(), db.password()),
                db.jdbcUrl()));
    }

    private static long count(Connection c, String table) throws SQLException {
        try (Statement s = c.createStatement(); ResultSet rs = s.executeQuery("SELECT COUNT(*) FROM " + table)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    @Test
    void h2IsNotSentRoundTrips() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2); HikariDataSource pool = multiStatementPool(db);
             Connection c = pool.getConnection()) {
            assertThat(RoundTrip.allowed(c)).as("a statement costs no round trip on H2").isFalse();
        }
    }

    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void itsStatementsCommitTogetherOrNotAtAll(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); HikariDataSource pool = multiStatementPool(db);
             Connection c = pool.getConnection()) {
            assertThat(RoundTrip.allowed(c)).isTrue();
            RoundTrip trip = twoInserts(3, "gps_stored_values");
            assertThat(trip.statements()).isEqualTo(2);
            assertThat(trip.commit(c)).as("each statement's update count").containsExactly(2, 1);
            assertThat(db.count("battery_level")).isEqualTo(2);
            assertThat(db.count("gps_stored_values")).isEqualTo(1);
            try (Statement s = c.createStatement(); ResultSet rs = s.executeQuery("SELECT x_m, y_m FROM gps_stored_values")) {
                rs.next();
                assertThat(rs.getDouble(1)).isEqualTo(1.25);
                assertThat(rs.getDouble(2)).isEqualTo(-2.5e-7);
            }

            assertThatThrownBy(() -> twoInserts(4, "no_such_table").commit(c)).isInstanceOf(SQLException.class)
                    .hasMessageContaining("no_such_table");
            assertThat(count(c, "battery_level")).as("the first insert rolled back, seen in its own session").isEqualTo(2);
            assertThat(inTransaction(c)).as("and the transaction ended").isZero();
            twoInserts(5, "gps_stored_values").commit(c);
            assertThat(db.count("battery_level")).as("the connection goes on").isEqualTo(4);

            RoundTrip update = new RoundTrip();
            update.add("UPDATE battery_level SET charging = TRUE WHERE robot_id = ?", 1, (ps, p) -> ps.setInt(p, 5));
            update.add("UPDATE battery_level SET charging = TRUE WHERE robot_id = ?", 1, (ps, p) -> ps.setInt(p, 99));
            assertThat(update.commit(c)).as("rows matched, none for a robot with no rows").containsExactly(2, 0);
        }
    }

    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void aConnectionThatRefusesMultiStatementsIsNotAllowedAndRunsNone(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); Connection plain = db.dataSource().getConnection()) {
            assertThat(RoundTrip.allowed(plain)).as("the plain pools do not allow them").isFalse();
            assertThatThrownBy(() -> twoInserts(3, "gps_stored_values").commit(plain))
                    .isInstanceOfSatisfying(SQLException.class, e -> assertThat(e.getErrorCode()).isEqualTo(1064));
            assertThat(db.count("battery_level")).isZero();
            assertThat(inTransaction(plain)).isZero();
        }
    }
}
