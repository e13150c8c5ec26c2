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
 * {@code START TRANSACTION; s1; s2; ...; COMMIT} in a single multi-statement text, on a connection
 * that allows multi-statements (the driver setting {@code allowMultiQueries=true}; see
 * {@link #allowed}), instead of a round trip per statement plus three for the transaction's
 * control. When a statement fails the server runs none after it, and this sends {@code ROLLBACK}.
 * Not for H2, where a statement costs no round trip.
 */
public final class RoundTrip implements Writes {

    /** MariaDB's and MySQL's syntax error: what a server says to multi-statements it does not allow. */
    private static final int ER_PARSE_ERROR = 1064;

    private final List<String> texts = new ArrayList<>();
    private final List<Binder> binders = new ArrayList<>();
    private final List<Integer> firsts = new ArrayList<>();
    private int parameters;
    private int statements;

    /**
     * Asks once per connection's pool, not per transaction: a MariaDB or MySQL connection is
     * tried with a two-statement query.
     *
     * @param c a connection
     * @return whether it takes a transaction as one round trip (MariaDB or MySQL, multi-statements allowed)
     * @throws SQLException when the connection fails otherwise than by refusing multi-statements
     */
    public static boolean allowed(Connection c) throws SQLException {
        if (MultiRow.isH2(c)) {
            return false;
        }
        String product = c.getMetaData().getDatabaseProductName().toLowerCase(Locale.ROOT);
        if (!product.contains("mariadb") && !product.contains("mysql")) {
            return false;
        }
        try (Statement s = c.createStatement()) {
            s.execute("SELECT 1; SELECT 2");
            while (s.getMoreResults() || s.getUpdateCount() != -1) {
                // drain both results
            }
            return true;
        } catch (SQLException e) {
            if (e.getErrorCode() == ER_PARSE_ERROR) {
                return false;
            }
            throw e;
        }
    }

    /** Keeps a statement for the round trip. */
    @Override
    public void add(String statement, int parameters, Binder binder) {
        texts.add(statement);
        firsts.add(this.parameters + 1);
        binders.add(binder);
        this.parameters += parameters;
        statements++;
    }

    /** Keeps rows for the round trip, in MariaDB's and MySQL's words. */
    @Override
    public void addRows(MultiRow words, int columns, int rows, MultiRow.RowBinder binder) {
        for (int from = 0; from < rows; from += MultiRow.MAX_ROWS) {
            int first = from;
            int n = Math.min(MultiRow.MAX_ROWS, rows - from);
            add(words.sql(false, n), n * columns, (ps, p) -> {
                for (int r = 0; r < n; r++) {
                    binder.bind(ps, p + r * columns, first + r);
                }
            });
        }
    }

    /**
     * Keeps another round trip's statements after these: several transactions' writes sent, and
     * committed, as one.
     *
     * @param other kept statements, not sent
     */
    public void addAll(RoundTrip other) {
        for (int i = 0; i < other.statements; i++) {
            int next = i + 1 < other.statements ? other.firsts.get(i + 1) : other.parameters + 1;
            add(other.texts.get(i), next - other.firsts.get(i), other.binders.get(i));
        }
    }

    /** @return how many statements were added (the transaction's control not counted) */
    public int statements() {
        return statements;
    }

    /**
     * Sends the statements and the commit as one round trip on a connection in auto-commit mode.
     * No statement time-out: MariaDB's driver would bound only the first statement of the text.
     *
     * @param c the connection; when this throws, give it back to a pool that discards broken
     *          connections (Hikari does): after an I/O error its state is not known
     * @return each added statement's update count, in the order added (-1 for a query)
     * @throws SQLException when a statement or the commit failed: none of them stays, but after an
     *         I/O error (a socket time-out, a dropped connection) whether the server committed is
     *         not known
     */
    public int[] commit(Connection c) throws SQLException {
        return commit(c, true);
    }

    /**
     * {@link #commit(Connection)}, saying whether the round trip opens its transaction (else one
     * is open on the connection already: {@code ...; COMMIT}).
     *
     * @param c       the connection
     * @param opening whether to send {@code START TRANSACTION} first
     * @return each added statement's update count, in the order added (-1 for a query)
     * @throws SQLException as {@link #commit(Connection)}
     */
    public int[] commit(Connection c, boolean opening) throws SQLException {
        String text = (opening ? "START TRANSACTION;\n" : "") + String.join(";\n", texts) + ";\nCOMMIT";
        int[] counts = new int[statements];
        try (PreparedStatement ps = c.prepareStatement(text)) {
            for (int i = 0; i < binders.size(); i++) {
                binders.get(i).bind(ps, firsts.get(i));
            }
            boolean resultSet = ps.execute();
            int result = opening ? -1 : 0; // START TRANSACTION's result is not a statement's
            while (resultSet || ps.getUpdateCount() != -1) { // every statement's result, so that an error is seen
                if (result >= 0 && result < statements) {
                    counts[result] = resultSet ? -1 : ps.getUpdateCount();
                }
                result++;
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
        return counts;
    }
}
