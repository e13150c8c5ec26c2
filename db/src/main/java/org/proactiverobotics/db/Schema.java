package org.proactiverobotics.db;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.DatabaseMetaData;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.sql.DataSource;

/**
 * The project's one schema (the root {@code schema.sql}, packaged in this jar) and the means to
 * apply it. Applying is idempotent: every statement is {@code CREATE ... IF NOT EXISTS}.
 */
public final class Schema {

    private static final String RESOURCE = "schema.sql";

    private Schema() {
    }

    /**
     * Creates every table that does not exist yet.
     *
     * @param dataSource the database
     * @throws SQLException naming the statement that failed
     */
    public static void apply(DataSource dataSource) throws SQLException {
        try (Connection connection = dataSource.getConnection(); Statement statement = connection.createStatement()) {
            for (String sql : statements()) {
                execute(statement, sql);
            }
            for (String[] added : ADDED_COLUMNS) {
                if (!hasColumn(statement, added[0], added[1])) {
                    execute(statement, "ALTER TABLE " + added[0] + " ADD COLUMN " + added[1] + " " + added[2]);
                }
            }
            for (String[] added : ADDED_INDEXES) {
                if (!hasIndex(connection, added[0], added[1])) {
                    execute(statement, "CREATE INDEX " + added[1] + " ON " + added[0] + " (" + added[2] + ")");
                }
            }
            boolean h2 = "H2".equalsIgnoreCase(connection.getMetaData().getDatabaseProductName());
            for (String[] superseded : SUPERSEDED_INDEXES) {
                if (hasIndex(connection, superseded[0], superseded[1])) { // H2 names indexes per schema, MySQL per table
                    execute(statement, h2 ? "DROP INDEX " + superseded[1] : "ALTER TABLE " + superseded[0] + " DROP INDEX " + superseded[1]);
                }
            }
        }
    }

    /**
     * Indexes added to a table after it first shipped: {table, index, columns}, each also in the
     * table's CREATE TABLE (MySQL 8 has no {@code CREATE INDEX IF NOT EXISTS}). The "newest" reads
     * went from id order to simulated-time and iteration order.
     */
    private static final String[][] ADDED_INDEXES = {
        {"gps_stored_values", "idx_gps_time", "robot_id, sim_time_ms, id"},
        {"iudata", "idx_iu_time", "robot_id, sim_time_ms, id"},
        {"battery_level", "idx_battery_time", "robot_id, sim_time_ms, id"},
        {"engine_comments", "idx_comments_iteration", "robot_id, iteration, id"},
    };

    /** Indexes no read uses any more, {table, index}: dropped from a database made before, so that no write keeps them up. */
    private static final String[][] SUPERSEDED_INDEXES = {
        {"gps_stored_values", "idx_gps_newest"},
        {"iudata", "idx_iu_newest"},
        {"battery_level", "idx_battery_newest"},
        {"engine_comments", "idx_comments_newest"},
    };

    private static boolean hasIndex(Connection connection, String table, String index) throws SQLException {
        DatabaseMetaData meta = connection.getMetaData();
        for (String name : new String[] {table, table.toUpperCase(Locale.ROOT)}) {
            try (ResultSet rs = meta.getIndexInfo(connection.getCatalog(), null, name, false, false)) {
                while (rs.next()) {
                    if (index.equalsIgnoreCase(rs.getString("INDEX_NAME"))) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /**
     * Columns added to a table after it first shipped: {table, column, definition}, each also in
     * the table's CREATE TABLE. A database made before gets them from {@link #apply}: MySQL 8 has
     * no {@code ADD COLUMN IF NOT EXISTS}, so the check is done here, the same on every database.
     */
    private static final String[][] ADDED_COLUMNS = {
        {"strategy", "timeout_ms", "BIGINT NOT NULL DEFAULT 0"},
        {"checkpoints", "unreachable", "BOOLEAN NOT NULL DEFAULT FALSE"},
        {"robot_body", "shared_world", "BOOLEAN NOT NULL DEFAULT FALSE"},
    };

    private static boolean hasColumn(Statement statement, String table, String column) {
        try (ResultSet rs = statement.executeQuery("SELECT " + column + " FROM " + table + " WHERE 1 = 0")) {
            return true;
        } catch (SQLException e) {
            return false;
        }
    }

    private static void execute(Statement statement, String sql) throws SQLException {
        try {
            statement.execute(sql);
        } catch (SQLException e) {
            throw new SQLException("schema.sql: statement failed: " + firstLine(sql) + ": " + e.getMessage(),
                    e.getSQLState(), e.getErrorCode(), e);
        }
    }

    /** @return schema.sql's text, as packaged */
    public static String text() {
        try (InputStream in = Schema.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("schema.sql is missing from the db jar");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** @return schema.sql split into statements, comments removed */
    public static List<String> statements() {
        return split(text());
    }

    /** @return the names of the tables schema.sql creates, in order */
    public static List<String> tableNames() {
        List<String> names = new ArrayList<>();
        for (String sql : statements()) {
            String[] words = sql.trim().split("\\s+");
            if (words.length > 5 && words[0].equalsIgnoreCase("CREATE") && words[1].equalsIgnoreCase("TABLE")) {
                names.add(words[5]);
            }
        }
        return names;
    }

    /**
     * Splits an SQL script into statements: a statement ends with ';' at the end of a line, and
     * "--" comment lines are dropped.
     *
     * @param script the script
     * @return its statements, without their ';'
     */
    public static List<String> split(String script) {
        List<String> out = new ArrayList<>();
        StringBuilder current = new StringBuilder();
        for (String line : script.split("\n")) {
            String trimmed = line.strip();
            if (trimmed.isEmpty() || trimmed.startsWith("--")) {
                continue;
            }
            current.append(line).append('\n');
            if (trimmed.endsWith(";")) {
                String sql = current.toString().strip();
                out.add(sql.substring(0, sql.length() - 1));
                current.setLength(0);
            }
        }
        if (!current.toString().isBlank()) {
            out.add(current.toString().strip());
        }
        return out;
    }

    private static String firstLine(String sql) {
        int newline = sql.indexOf('\n');
        return newline < 0 ? sql : sql.substring(0, newline);
    }
}
