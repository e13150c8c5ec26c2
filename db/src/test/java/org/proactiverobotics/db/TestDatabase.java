package org.proactiverobotics.db;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import javax.sql.DataSource;

/**
 * A fresh database with schema.sql applied, for one test. Closing it closes the pool and drops
 * the database.
 */
public final class TestDatabase implements AutoCloseable {

    private final DatabaseKind kind;
    private final String jdbcUrl;
    private final String user;
    private final String password;
    private final HikariDataSource dataSource;
    private final Runnable drop;

    TestDatabase(DatabaseKind kind, String jdbcUrl, String user, String password, Runnable drop) throws SQLException {
        this.kind = kind;
        this.jdbcUrl = jdbcUrl;
        this.user = user;
        this.password = password;
        this.drop = drop;
        this.dataSource = Databases.pool(jdbcUrl, user, password);
        Schema.apply(dataSource);
    }

    /** @return which kind of database this is */
    public DatabaseKind kind() {
        return kind;
    }

    /** @return the JDBC URL of this database (for a second pool, or a second process) */
    public String jdbcUrl() {
        return jdbcUrl;
    }

    /** @return the user, or null when the URL carries it */
    public String user() {
        return user;
    }

    /** @return the password, or null when the URL carries it */
    public String password() {
        return password;
    }

    /** @return the pool over this database */
    public DataSource dataSource() {
        return dataSource;
    }

    /** Runs one SQL statement, for test set-up. */
    public void execute(String sql) throws SQLException {
        try (Connection c = dataSource.getConnection(); Statement s = c.createStatement()) {
            s.execute(sql);
        }
    }

    /** Counts the rows of a table. */
    public long count(String table) throws SQLException {
        try (Connection c = dataSource.getConnection(); Statement s = c.createStatement();
             var rs = s.executeQuery("SELECT COUNT(*) FROM " + table)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    @Override
    public void close() {
        dataSource.close();
        drop.run();
    }

    @Override
    public String toString() {
        return kind + " " + jdbcUrl;
    }
}
