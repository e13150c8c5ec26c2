package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
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
            insert.write(c, 3, (ps, p, r) -> {
                ps.setInt(p, 7);
                ps.setInt(p + 1, r);
                ps.setString(p + 2, "T" + r);
                ps.setString(p + 3, "{}");
            });
            assertThat(db.count("engine_queue")).isEqualTo(3);
            MultiRow upsert = MultiRow.upsert("engine_queue", List.of("robot_id", "position"),
                    "robot_id", "position", "rule_type", "rule_json");
            assertThat(MultiRow.isH2(c)).isEqualTo(kind == DatabaseKind.H2);
            Object[][] rows = {{7, 1, "changed", "{\"a\":1}"}, {7, 3, "new", "{}"}};
            upsert.write(c, rows.length, (ps, p, r) -> {
                for (int k = 0; k < rows[r].length; k++) {
                    ps.setObject(p + k, rows[r][k]);
                }
            });
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
        assertThat(insert.sql(false, 2)).isEqualTo("INSERT INTO t (a, b) VALUES (?, ?), (?, ?)");
        assertThat(MultiRow.upsert("t", List.of("a"), "a", "b").sql(false, 1))
                .isEqualTo("INSERT INTO t (a, b) VALUES (?, ?) ON DUPLICATE KEY UPDATE b = VALUES(b)");
        assertThat(MultiRow.upsert("t", List.of("a"), "a", "b").sql(true, 1)).isEqualTo("MERGE INTO t (a, b) KEY (a) VALUES (?, ?)");
        assertThatThrownBy(() -> insert.sql(false, 0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> insert.sql(false, MultiRow.MAX_ROWS + 1)).isInstanceOf(IllegalArgumentException.class);
    }
}
