package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;

/**
 * Where a transaction's writes go when nobody reads their results: run at once on a connection
 * ({@link #atOnce}), or kept and sent with the commit as one round trip ({@link RoundTrip}). The
 * writer does not need to know which.
 */
public interface Writes {

    /** Binds one statement's values. */
    @FunctionalInterface
    interface Binder {
        /**
         * @param ps    the statement (in a round trip, the whole round trip's)
         * @param first the parameter index of this statement's first value
         * @throws SQLException from the driver
         */
        void bind(PreparedStatement ps, int first) throws SQLException;
    }

    /**
     * @param statement  one SQL statement, without a semicolon
     * @param parameters how many '?' it has
     * @param binder     binds them from the index it is given
     * @throws SQLException when run at once and it fails
     */
    void add(String statement, int parameters, Binder binder) throws SQLException;

    /**
     * Rows as multi-row statements of {@code words}, in the connection's dialect, as few as
     * {@link MultiRow#MAX_ROWS} allows.
     *
     * @param words   the statement's words
     * @param columns how many values a row has
     * @param rows    how many rows (none: nothing is written)
     * @param binder  binds row r's values from the given parameter index
     * @throws SQLException when run at once and it fails
     */
    void addRows(MultiRow words, int columns, int rows, MultiRow.RowBinder binder) throws SQLException;

    /**
     * @param c the connection (its transaction is the caller's)
     * @return writes run on it as they are added
     */
    static Writes atOnce(Connection c) {
        return atOnce(c, 0);
    }

    /**
     * @param c             the connection (its transaction is the caller's)
     * @param queryTimeoutS each statement's time-out, seconds, or 0 for none
     * @return writes run on it as they are added
     */
    static Writes atOnce(Connection c, int queryTimeoutS) {
        return new Writes() {
            @Override
            public void add(String statement, int parameters, Binder binder) throws SQLException {
                try (PreparedStatement ps = c.prepareStatement(statement)) {
                    if (queryTimeoutS > 0) {
                        ps.setQueryTimeout(queryTimeoutS);
                    }
                    binder.bind(ps, 1);
                    ps.executeUpdate();
                }
            }

            @Override
            public void addRows(MultiRow words, int columns, int rows, MultiRow.RowBinder binder) throws SQLException {
                words.write(c, queryTimeoutS, rows, binder);
            }
        };
    }
}
