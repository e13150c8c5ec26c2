package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;

/**
 * One statement for many rows of one table: {@code INSERT ... VALUES (?, ?), (?, ?), ...}, or the
 * same as an upsert in the words each database takes ({@code MERGE ... KEY} on H2, which runs
 * {@code ON DUPLICATE KEY} as a failed insert and a freshly parsed update per row; {@code ON
 * DUPLICATE KEY UPDATE} on MariaDB and MySQL). One statement is one parse and one round trip
 * however many rows it carries, where a JDBC batch is a statement per row on H2 and, on a driver
 * that does not bulk-send, a round trip per row. {@link #write} sends any number of rows, at most
 * {@value #MAX_ROWS} a statement. Thread-safe.
 */
public final class MultiRow {

    /** H2's connection class, or null when H2 is not on the class path (then no connection is H2's). */
    private static final Class<?> H2_CONNECTION = h2Connection();

    private static Class<?> h2Connection() {
        try {
            return Class.forName("org.h2.jdbc.JdbcConnection", false, MultiRow.class.getClassLoader());
        } catch (ClassNotFoundException e) {
            return null;
        }
    }

    /** The most rows one statement carries; {@link #write} sends more as several statements. */
    public static final int MAX_ROWS = 128;

    /** Binds one row's values. */
    @FunctionalInterface
    public interface RowBinder {
        /**
         * @param ps    the statement
         * @param first the parameter index of the row's first column
         * @param row   the row's index among those written, from 0
         * @throws SQLException from the driver
         */
        void bind(PreparedStatement ps, int first, int row) throws SQLException;
    }

    private final int columns;
    private final Words words;
    /** H2's words for an upsert, or null when they are the same as everyone's (an insert). */
    private final Words h2Words;

    /** One statement's text around its rows, with the texts for each row count kept once made. */
    private static final class Words {
        private final String head;
        private final String tail;
        private final int columns;
        private final String[] byRows = new String[MAX_ROWS + 1];

        Words(String head, String tail, int columns) {
            this.head = head;
            this.tail = tail;
            this.columns = columns;
        }

        String sql(int rows) {
            if (rows < 1 || rows > MAX_ROWS) {
                throw new IllegalArgumentException("rows must be 1 to " + MAX_ROWS + ": " + rows);
            }
            String s = byRows[rows];
            if (s == null) {
                StringBuilder b = new StringBuilder(head.length() + tail.length() + rows * (3 * columns + 4));
                b.append(head);
                for (int r = 0; r < rows; r++) {
                    b.append(r == 0 ? "(" : ", (");
                    for (int k = 0; k < columns; k++) {
                        b.append(k == 0 ? "?" : ", ?");
                    }
                    b.append(')');
                }
                s = b.append(tail).toString();
                byRows[rows] = s; // a race writes the same string twice
            }
            return s;
        }
    }

    private MultiRow(int columns, Words words, Words h2Words) {
        this.columns = columns;
        this.words = words;
        this.h2Words = h2Words;
    }

    /**
     * @param table   the table
     * @param columns its columns, in the order the parameters are bound
     * @return a multi-row INSERT
     */
    public static MultiRow insert(String table, String... columns) {
        String head = "INSERT INTO " + table + " (" + String.join(", ", columns) + ") VALUES ";
        return new MultiRow(columns.length, new Words(head, "", columns.length), null);
    }

    /**
     * @param table   the table
     * @param key     the columns of its primary key, all among {@code columns}
     * @param columns its columns, in the order the parameters are bound
     * @return a multi-row upsert: a row whose key exists replaces that row's other columns
     */
    public static MultiRow upsert(String table, List<String> key, String... columns) {
        String list = " (" + String.join(", ", columns) + ")";
        List<String> set = new ArrayList<>();
        for (String c : columns) {
            if (!key.contains(c)) {
                set.add(c + " = VALUES(" + c + ")");
            }
        }
        return new MultiRow(columns.length,
                new Words("INSERT INTO " + table + list + " VALUES ", " ON DUPLICATE KEY UPDATE " + String.join(", ", set), columns.length),
                new Words("MERGE INTO " + table + list + " KEY (" + String.join(", ", key) + ") VALUES ", "", columns.length));
    }

    /**
     * @param c a connection (a pool's proxy too)
     * @return whether it is to H2
     * @throws SQLException when the connection cannot say
     */
    public static boolean isH2(Connection c) throws SQLException {
        // a class check through the pool's proxy: asked on every upsert, where metadata was an object a call
        return H2_CONNECTION != null && c.isWrapperFor(H2_CONNECTION);
    }

    /**
     * @param h2   whether the statement is for H2
     * @param rows how many rows, 1 to {@link #MAX_ROWS}
     * @return the statement for that many rows
     */
    public String sql(boolean h2, int rows) {
        return (h2 && h2Words != null ? h2Words : words).sql(rows);
    }

    /**
     * Sends rows in as few statements as {@link #MAX_ROWS} allows (one, nearly always), in the
     * words the connection's database takes.
     *
     * @param c             the connection (its transaction is the caller's)
     * @param queryTimeoutS each statement's time-out, seconds, or 0 for none
     * @param rows          how many rows (none: nothing is sent)
     * @param binder        binds row r's values from the given parameter index
     * @throws SQLException from the driver
     */
    public void write(Connection c, int queryTimeoutS, int rows, RowBinder binder) throws SQLException {
        boolean h2 = rows > 0 && h2Words != null && isH2(c); // only an upsert's words differ
        for (int from = 0; from < rows; from += MAX_ROWS) {
            int n = Math.min(MAX_ROWS, rows - from);
            try (PreparedStatement ps = c.prepareStatement(sql(h2, n))) {
                if (queryTimeoutS > 0) {
                    ps.setQueryTimeout(queryTimeoutS);
                }
                for (int r = 0; r < n; r++) {
                    binder.bind(ps, r * columns + 1, from + r);
                }
                ps.executeUpdate();
            }
        }
    }

    /** {@link #write(Connection, int, int, RowBinder)} without a time-out. */
    public void write(Connection c, int rows, RowBinder binder) throws SQLException {
        write(c, 0, rows, binder);
    }
}
