package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** A database made before a column or an index was added gets it when the schema is applied again. */
class SchemaUpgradeTest {

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aStrategyTableWithoutTimeOutsGetsTheColumnWithZeroForItsRows(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            db.execute("DROP TABLE strategy");
            db.execute("CREATE TABLE strategy (robot_id INT NOT NULL, slot INT NOT NULL, scenario VARCHAR(64) NOT NULL,"
                    + " priority INT NOT NULL, strategy_name VARCHAR(64) NOT NULL,"
                    + " updated_at TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3), PRIMARY KEY (robot_id, slot))");
            db.execute("INSERT INTO strategy (robot_id, slot, scenario, priority, strategy_name) VALUES (1, 2, 'A', 3, 'old')");
            Schema.apply(db.dataSource());
            Schema.apply(db.dataSource()); // and again: harmless
            try (Connection c = db.dataSource().getConnection(); Statement s = c.createStatement();
                 ResultSet rs = s.executeQuery("SELECT timeout_ms FROM strategy WHERE robot_id = 1")) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getLong(1)).isZero();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void checkpointsMadeBeforeRoutesGetTheUnreachableColumnFalseForTheirRows(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            db.execute("DROP TABLE checkpoints");
            db.execute("CREATE TABLE checkpoints (robot_id INT NOT NULL, seq INT NOT NULL, x_m DOUBLE NOT NULL,"
                    + " y_m DOUBLE NOT NULL, radius_m DOUBLE NOT NULL, reached BOOLEAN NOT NULL DEFAULT FALSE,"
                    + " reached_sim_time_ms BIGINT, PRIMARY KEY (robot_id, seq))");
            db.execute("INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m) VALUES (1, 0, 1.0, 2.0, 0.25)");
            Schema.apply(db.dataSource());
            Schema.apply(db.dataSource());
            try (Connection c = db.dataSource().getConnection(); Statement s = c.createStatement();
                 ResultSet rs = s.executeQuery("SELECT unreachable FROM checkpoints WHERE robot_id = 1")) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getBoolean(1)).isFalse();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void readingAndCommandTablesMadeWithIdIndexesGetTheTimeAndIterationIndexesInstead(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            db.execute("DROP TABLE gps_stored_values");
            db.execute("CREATE TABLE gps_stored_values (id BIGINT AUTO_INCREMENT PRIMARY KEY, robot_id INT NOT NULL,"
                    + " sim_time_ms BIGINT NOT NULL, x_m DOUBLE NOT NULL, y_m DOUBLE NOT NULL, INDEX idx_gps_newest (robot_id, id))");
            db.execute("DROP TABLE engine_comments");
            db.execute("CREATE TABLE engine_comments (id BIGINT AUTO_INCREMENT PRIMARY KEY, robot_id INT NOT NULL,"
                    + " iteration BIGINT NOT NULL, sim_time_ms BIGINT NOT NULL, scenario VARCHAR(64) NOT NULL,"
                    + " command VARCHAR(255) NOT NULL, created_at TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3),"
                    + " INDEX idx_comments_newest (robot_id, id))");
            db.execute("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (1, 32, 0.5, 1.5)");
            assertThat(indexes(db, "gps_stored_values")).contains("idx_gps_newest").doesNotContain("idx_gps_time");
            Schema.apply(db.dataSource());
            Schema.apply(db.dataSource()); // and again: harmless
            assertThat(indexes(db, "gps_stored_values")).contains("idx_gps_time").doesNotContain("idx_gps_newest");
            assertThat(indexes(db, "engine_comments")).contains("idx_comments_iteration").doesNotContain("idx_comments_newest");
            assertThat(indexes(db, "iudata")).contains("idx_iu_time");
            assertThat(indexes(db, "battery_level")).contains("idx_battery_time");
            try (Connection c = db.dataSource().getConnection(); Statement s = c.createStatement();
                 ResultSet rs = s.executeQuery("SELECT COUNT(*) FROM gps_stored_values")) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getLong(1)).isOne();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aDatabaseMadeBeforeOdometryGetsTheTableAndItsTimeIndexItsRowsUntouched(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            db.execute("DROP TABLE odometry");
            db.execute("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (1, 32, 0.5, 1.5)");
            Schema.apply(db.dataSource());
            Schema.apply(db.dataSource()); // and again: harmless
            assertThat(indexes(db, "odometry")).contains("idx_odometry_time");
            db.execute("INSERT INTO odometry (robot_id, sim_time_ms, left_m, right_m) VALUES (1, 64, 0.016, -0.016)");
            assertThat(db.count("odometry")).isOne();
            assertThat(db.count("gps_stored_values")).isOne();
        }
    }

    private static java.util.Set<String> indexes(TestDatabase db, String table) throws Exception {
        java.util.Set<String> names = new java.util.TreeSet<>();
        try (Connection c = db.dataSource().getConnection()) {
            for (String name : new String[] {table, table.toUpperCase(java.util.Locale.ROOT)}) {
                try (ResultSet rs = c.getMetaData().getIndexInfo(c.getCatalog(), null, name, false, false)) {
                    while (rs.next()) {
                        String index = rs.getString("INDEX_NAME");
                        if (index != null) {
                            names.add(index.toLowerCase(java.util.Locale.ROOT));
                        }
                    }
                }
            }
        }
        return names;
    }
}
