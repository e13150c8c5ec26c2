package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;

/**
 * One statement for many rows of one table: {@code INSERT ... VALUES (?, ?), (?, ?), ...}, or the
 * same as an upsert in the words each database takes ({@code MERGE ... KEY} on H2, {@code ON
 * DUPLICATE KEY UPDATE} on MariaDB and MySQL). One statement is one parse and one round trip
 * however many rows it carries, where a JDBC batch is a statement per row on H2 and, on a driver
 * that does not bulk-send, a round trip per row. Parameters go row after row: row r's column c
 * (both from 0) is parameter {@code r * columns() + c + 1}. Thread-safe.
 */
public final class MultiRow {

    /** The most rows one statement carries; callers send more as several statements. */
    public static final int MAX_ROWS = 128;

    private final String head;
    private final String tail;
    private final int columns;
    private final String[] byRows = new String[MAX_ROWS + 1];

    private MultiRow(String head, String tail, int columns) {
        this.head = head;
        this.tail = tail;
        this.columns = columns;
    }

    /**
     * @param table   the table
     * @param columns its columns, in the order the parameters are bound
     * @return a multi-row INSERT
     */
    public static MultiRow insert(String table, String... columns) {
        return new MultiRow("INSERT INTO " + table + " (" + String.join(", ", columns) + ") VALUES ", "", columns.length);
    }

    /**
     * @param h2      whether the database is H2 (see {@link #isH2(Connection)})
     * @param table   the table
     * @param key     the columns of its primary key, all among {@code columns}
     * @param columns its columns, in the order the parameters are bound
     * @return a multi-row upsert: a row whose key exists replaces that row's other columns
     */
    public static MultiRow upsert(boolean h2, String table, List<String> key, String... columns) {
        String list = " (" + String.join(", ", columns) + ")";
        if (h2) {
            return new MultiRow("MERGE INTO " + table + list + " KEY (" + String.join(", ", key) + ") VALUES ", "", columns.length);
        }
        List<String> set = new ArrayList<>();
        for (String c : columns) {
            if (!key.contains(c)) {
                set.add(c + " = VALUES(" + c + ")");
            }
        }
        return new MultiRow("INSERT INTO " + table + list + " VALUES ", " ON DUPLICATE KEY UPDATE " + String.join(", ", set),
                columns.length);
    }

    /**
     * @param c a connection
     * @return whether it is to H2 (which runs {@code ON DUPLICATE KEY} as a failed insert and a freshly parsed update per row)
     * @throws SQLException when the connection cannot say
     */
    public static boolean isH2(Connection c) throws SQLException {
        return "H2".equals(c.getMetaData().getDatabaseProductName());
    }

    /** @return the columns per row */
    public int columns() {
        return columns;
    }

    /**
     * @param rows how many rows, 1 to {@link #MAX_ROWS}
     * @return the statement for that many rows
     */
    public String sql(int rows) {
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
