package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One transaction sent to a MariaDB or MySQL server as one round trip:
 * {@code START TRANSACTION; s1; s2; ...; COMMIT} in a single multi-statement text (the pools of
 * {@link Databases} allow multi-statements on those drivers), instead of a round trip per statement
 * plus three for the transaction's control. All or nothing: when a statement fails the server runs
 * none after it, and this sends {@code ROLLBACK}. Not for H2, where a statement costs no round trip.
 */
public final class RoundTrip {

    /** Binds one statement's values. */
    @FunctionalInterface
    public interface Binder {
        /**
         * @param ps    the whole round trip's statement
         * @param first the parameter index of this statement's first value
         * @throws SQLException from the driver
         */
        void bind(PreparedStatement ps, int first) throws SQLException;
    }

    private final StringBuilder sql = new StringBuilder("START TRANSACTION");
    private final List<Binder> binders = new ArrayList<>();
    private final List<Integer> firsts = new ArrayList<>();
    private int parameters;
    private int statements;

    /**
     * @param c a connection
     * @return whether its server takes a transaction as one round trip (MariaDB, MySQL)
     * @throws SQLException when the connection cannot say
     */
    public static boolean supported(Connection c) throws SQLException {
        if (MultiRow.isH2(c)) {
            return false;
        }
        String product = c.getMetaData().getDatabaseProductName().toLowerCase(Locale.ROOT);
        return product.contains("mariadb") || product.contains("mysql");
    }

    /**
     * Adds a statement.
     *
     * @param statement  one SQL statement, without a semicolon
     * @param parameters how many '?' it has
     * @param binder     binds them from the index it is given
     * @return this
     */
    public RoundTrip add(String statement, int parameters, Binder binder) {
        sql.append(";\n").append(statement);
        firsts.add(this.parameters + 1);
        binders.add(binder);
        this.parameters += parameters;
        statements++;
        return this;
    }

    /**
     * Adds rows as one multi-row statement of {@code insert}'s words.
     *
     * @param insert  the statement's words
     * @param columns how many values a row has
     * @param rows    how many rows, 1 to {@link MultiRow#MAX_ROWS} (none: nothing is added)
     * @param binder  binds row r's values from the given parameter index
     * @return this
     */
    public RoundTrip addRows(MultiRow insert, int columns, int rows, MultiRow.RowBinder binder) {
        if (rows == 0) {
            return this;
        }
        if (rows > MultiRow.MAX_ROWS) {
            throw new IllegalArgumentException("at most " + MultiRow.MAX_ROWS + " rows in one statement: " + rows);
        }
        return add(insert.sql(false, rows), rows * columns, (ps, first) -> {
            for (int r = 0; r < rows; r++) {
                binder.bind(ps, first + r * columns, r);
            }
        });
    }

    /** @return how many statements were added (the transaction's control not counted) */
    public int statements() {
        return statements;
    }

    /**
     * Sends the statements and the commit as one round trip on a connection in auto-commit mode.
     *
     * @param c             the connection
     * @param queryTimeoutS the round trip's time-out, seconds, or 0 for none
     * @throws SQLException when a statement or the commit failed: nothing of them stays
     */
    public void commit(Connection c, int queryTimeoutS) throws SQLException {
        String text = sql + ";\nCOMMIT";
        try (PreparedStatement ps = c.prepareStatement(text)) {
            if (queryTimeoutS > 0) {
                ps.setQueryTimeout(queryTimeoutS);
            }
            for (int i = 0; i < binders.size(); i++) {
                binders.get(i).bind(ps, firsts.get(i));
            }
            boolean resultSet = ps.execute();
            while (resultSet || ps.getUpdateCount() != -1) { // every statement's result, so that an error is seen
                resultSet = ps.getMoreResults();
            }
        } catch (SQLException e) {
            // the server stopped at the failed statement, inside the transaction: end it
            try (Statement s = c.createStatement()) {
                s.execute("ROLLBACK");
            } catch (SQLException rollback) {
                e.addSuppressed(rollback);
            }
            throw e;
        }
    }
}
