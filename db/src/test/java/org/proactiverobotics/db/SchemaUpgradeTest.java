package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** A database made before a column was added gets it when the schema is applied again. */
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
}
