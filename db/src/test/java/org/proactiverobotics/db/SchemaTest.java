package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.ResultSet;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class SchemaTest {

    private static final List<String> PAPER_TABLES = List.of("battery_level", "battery_recharged", "checkpoints",
            "distance_sensor_data", "engine_comments", "gps_stored_values", "iudata", "recharge_station");

    @Test
    void schemaCreatesThePapersEightTablesAndTheEnginesOwn() {
        assertThat(Schema.tableNames()).containsAll(PAPER_TABLES)
                .contains("sensor_requests", "strategy", "engine_state", "engine_queue", "rule_failures");
    }

    @Test
    void splitterDropsCommentsAndKeepsStatementsWhole() {
        List<String> parts = Schema.split("-- a comment\nCREATE TABLE a (\n x INT\n);\n\nCREATE TABLE b (y INT);\n");
        assertThat(parts).containsExactly("CREATE TABLE a (\n x INT\n)", "CREATE TABLE b (y INT)");
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void schemaAppliesTwiceAndEveryTableHasRobotId(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            Schema.apply(db.dataSource()); // second time: must be harmless
            try (Connection c = db.dataSource().getConnection()) {
                for (String table : Schema.tableNames()) {
                    List<String> columns = new ArrayList<>();
                    try (ResultSet rs = c.getMetaData().getColumns(c.getCatalog(), null, table, null)) {
                        while (rs.next()) {
                            columns.add(rs.getString("COLUMN_NAME").toLowerCase());
                        }
                    }
                    assertThat(columns).as(table).contains("robot_id");
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void newestReadingComesFromTheRobotsOwnRowsByTimeNotId(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            // Ids as two Galera nodes hand them out: the newest reading has the smaller id.
            db.execute("INSERT INTO gps_stored_values (id, robot_id, sim_time_ms, x_m, y_m) VALUES (10, 1, 32, 0.5, 1.5)");
            db.execute("INSERT INTO gps_stored_values (id, robot_id, sim_time_ms, x_m, y_m) VALUES (11, 2, 96, 9.0, 9.0)");
            db.execute("INSERT INTO gps_stored_values (id, robot_id, sim_time_ms, x_m, y_m) VALUES (8, 1, 64, 0.6, 1.4)");
            try (Connection c = db.dataSource().getConnection();
                 var ps = c.prepareStatement("SELECT x_m, sim_time_ms FROM gps_stored_values WHERE robot_id = ?"
                         + " ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1")) {
                ps.setInt(1, 1);
                try (ResultSet rs = ps.executeQuery()) {
                    assertThat(rs.next()).isTrue();
                    assertThat(rs.getDouble(1)).isEqualTo(0.6);
                    assertThat(rs.getLong(2)).isEqualTo(64);
                }
            }
        }
    }
}
