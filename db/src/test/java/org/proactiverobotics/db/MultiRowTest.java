package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Many rows in one statement: inserted, and upserted in each database's own words. */
class MultiRowTest {

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void rowsGoInAsOneStatementAndAnUpsertReplacesOnlyTheRowsItNames(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); Connection c = db.dataSource().getConnection()) {
            MultiRow insert = MultiRow.insert("engine_queue", "robot_id", "position", "rule_type", "rule_json");
            try (PreparedStatement ps = c.prepareStatement(insert.sql(3))) {
                for (int r = 0; r < 3; r++) {
                    ps.setInt(r * 4 + 1, 7);
                    ps.setInt(r * 4 + 2, r);
                    ps.setString(r * 4 + 3, "T" + r);
                    ps.setString(r * 4 + 4, "{}");
                }
                assertThat(ps.executeUpdate()).isEqualTo(3);
            }
            MultiRow upsert = MultiRow.upsert(MultiRow.isH2(c), "engine_queue", List.of("robot_id", "position"),
                    "robot_id", "position", "rule_type", "rule_json");
            assertThat(MultiRow.isH2(c)).isEqualTo(kind == DatabaseKind.H2);
            try (PreparedStatement ps = c.prepareStatement(upsert.sql(2))) {
                Object[][] rows = {{7, 1, "changed", "{\"a\":1}"}, {7, 3, "new", "{}"}};
                int p = 1;
                for (Object[] row : rows) {
                    for (Object v : row) {
                        ps.setObject(p++, v);
                    }
                }
                ps.executeUpdate();
            }
            List<String> seen = new ArrayList<>();
            try (ResultSet rs = c.createStatement().executeQuery(
                    "SELECT position, rule_type, rule_json FROM engine_queue WHERE robot_id = 7 ORDER BY position")) {
                while (rs.next()) {
                    seen.add(rs.getInt(1) + " " + rs.getString(2) + " " + rs.getString(3));
                }
            }
            assertThat(seen).containsExactly("0 T0 {}", "1 changed {\"a\":1}", "2 T2 {}", "3 new {}");
        }
    }

    @Test
    void theStatementHasAPlaceholderPerCellAndRefusesNoRowsOrTooMany() {
        MultiRow insert = MultiRow.insert("t", "a", "b");
        assertThat(insert.sql(2)).isEqualTo("INSERT INTO t (a, b) VALUES (?, ?), (?, ?)");
        assertThat(MultiRow.upsert(false, "t", List.of("a"), "a", "b").sql(1))
                .isEqualTo("INSERT INTO t (a, b) VALUES (?, ?) ON DUPLICATE KEY UPDATE b = VALUES(b)");
        assertThat(MultiRow.upsert(true, "t", List.of("a"), "a", "b").sql(1)).isEqualTo("MERGE INTO t (a, b) KEY (a) VALUES (?, ?)");
        assertThatThrownBy(() -> insert.sql(0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> insert.sql(MultiRow.MAX_ROWS + 1)).isInstanceOf(IllegalArgumentException.class);
    }
}
