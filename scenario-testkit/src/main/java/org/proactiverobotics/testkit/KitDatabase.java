package org.proactiverobotics.testkit;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import javax.sql.DataSource;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.Schema;

/**
 * The database a kit runs on, and the plain SQL the kit's robot and its assertions use: a
 * fresh embedded H2 the kit owns (dropped on close), or one the test gives (left as it is).
 */
final class KitDatabase implements AutoCloseable {

    /** Maps one result row. */
    interface Row<T> {
        T map(ResultSet rs) throws SQLException;
    }

    private final DataSource dataSource;
    private final HikariDataSource owned;

    private KitDatabase(DataSource dataSource, HikariDataSource owned) {
        this.dataSource = dataSource;
        this.owned = owned;
    }

    /** @return a fresh in-memory H2 database in MySQL mode with the schema applied */
    static KitDatabase embeddedH2() {
        String name = "kit_" + UUID.randomUUID().toString().replace("-", "").substring(0, 12);
        HikariDataSource pool = Databases.pool(Databases.embeddedH2Url(name), "sa", "");
        KitDatabase db = new KitDatabase(pool, pool);
        db.applySchema();
        return db;
    }

    /** @return the given database, the schema applied where a table is missing */
    static KitDatabase given(DataSource dataSource) {
        KitDatabase db = new KitDatabase(dataSource, null);
        db.applySchema();
        return db;
    }

    private void applySchema() {
        try {
            Schema.apply(dataSource);
        } catch (SQLException e) {
            close();
            throw new ScenarioKitException("applying the schema to the kit's database: " + e.getMessage(), e);
        }
    }

    DataSource dataSource() {
        return dataSource;
    }

    void update(String sql, Object... params) {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
            for (int i = 0; i < params.length; i++) {
                ps.setObject(i + 1, params[i]);
            }
            ps.executeUpdate();
        } catch (SQLException e) {
            throw new ScenarioKitException(sql + " " + List.of(params) + ": " + e.getMessage(), e);
        }
    }

    <T> List<T> query(String sql, Row<T> row, Object... params) {
        List<T> out = new ArrayList<>();
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
            for (int i = 0; i < params.length; i++) {
                ps.setObject(i + 1, params[i]);
            }
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    out.add(row.map(rs));
                }
            }
        } catch (SQLException e) {
            throw new ScenarioKitException(sql + ": " + e.getMessage(), e);
        }
        return out;
    }

    /** Drops the database the kit made; a given one is the test's to close. */
    @Override
    public void close() {
        if (owned == null || owned.isClosed()) {
            return;
        }
        try (Connection c = owned.getConnection(); Statement s = c.createStatement()) {
            s.execute("DROP ALL OBJECTS");
            s.execute("SHUTDOWN");
        } catch (SQLException e) {
            // the pool goes anyway; an in-memory database left behind dies with the JVM
        } finally {
            owned.close();
        }
    }
}
