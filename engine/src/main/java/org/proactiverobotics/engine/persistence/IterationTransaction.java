package org.proactiverobotics.engine.persistence;

import java.io.PrintWriter;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.SQLFeatureNotSupportedException;
import java.sql.SQLNonTransientConnectionException;
import java.sql.SQLRecoverableException;
import java.sql.SQLTransientConnectionException;
import java.sql.Statement;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Logger;
import javax.sql.DataSource;
import org.proactiverobotics.db.RoundTrip;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.engine.StateStoreException;

/**
 * One database transaction per engine iteration, on one explicit connection: between
 * {@link #begin()} and {@link #commit()} the iteration's thread gets that connection from
 * {@link #connection()} and runs its statements on it without committing or closing it. The
 * rules' tables and the {@link JdbcStateStore} do so: an iteration's writes (commands, requests,
 * marks, buffered until {@link #commit()} by whoever registered {@link #beforeCommit}) and its
 * saved state then commit together, once — all of an iteration or none of it survives a crash,
 * and a server that flushes its log at every commit does so once per iteration.
 * {@link #getConnection()} is always the plain pool (outside the iteration's transaction).
 *
 * <p>On MariaDB and MySQL (multi-statements allowed) the transaction costs no round trip of its
 * own: the connection stays in auto-commit mode (no {@code set autocommit} before and after), the
 * iteration's reads run before the transaction opens ({@link #readConnection()}; the pools read
 * committed rows either way), the first write that must run at once opens it in the same round
 * trip ({@link #sendNow}), and the writes kept for the commit go with {@code COMMIT}. A caller
 * that takes {@link #connection()} gets the transaction opened first, so nothing it writes can
 * escape it. The iterations of several robots that one thread runs one after the other can
 * commit as one transaction ({@link CommitGroup}).
 */
public final class IterationTransaction implements DataSource {

    /**
     * Work run just before the iteration commits: writes kept for the commit go to
     * {@link #writes()}; a statement that must run now takes {@link #connection()}.
     */
    @FunctionalInterface
    public interface BeforeCommit {
        /** @throws SQLException to roll the iteration back */
        void run() throws SQLException;
    }

    /** MariaDB's and MySQL's deadlock: the server rolled the whole transaction back. */
    private static final int ER_LOCK_DEADLOCK = 1213;
    private static final String START_TRANSACTION = "START TRANSACTION";
    private static final String ROLLBACK_THEN_START = "ROLLBACK;\nSTART TRANSACTION";
    /** MariaDB's and MySQL's lock wait time-out: the statement, or the transaction, rolled back. */
    private static final int ER_LOCK_WAIT_TIMEOUT = 1205;

    private final DataSource pool;
    private final List<Runnable> rollbackListeners = new CopyOnWriteArrayList<>();
    private final List<BeforeCommit> beforeCommit = new CopyOnWriteArrayList<>();
    private final List<Runnable> commitListeners = new CopyOnWriteArrayList<>();
    /** The group the next (or the open) iteration commits with, or null: it commits alone. */
    private CommitGroup group;
    private Connection shared;
    /** Whether the pool's connections take multi-statements (MariaDB, MySQL); null until the first iteration. */
    private Boolean multiStatements;
    /** The open iteration's writes that are sent with its commit, or null (they run at once instead). */
    private RoundTrip deferred;
    /** Where the open iteration's writes go: {@link #deferred}, or its connection at once. */
    private Writes writes;
    /** With multi-statements, outside a group: whether START TRANSACTION was sent (else the iteration has only read). */
    private boolean serverTransaction;
    private Thread owner;
    private boolean rollbackOnly;
    private long number;

    /** @param pool the connection pool */
    public IterationTransaction(DataSource pool) {
        this.pool = pool;
    }

    /**
     * Registers what to do when an iteration's transaction does not commit (a cache of what was
     * believed written, for instance).
     *
     * @param listener run after the rollback, on the iteration's thread
     */
    public void onRollback(Runnable listener) {
        rollbackListeners.add(listener);
    }

    /**
     * Registers what to do once an iteration is in the database (housekeeping that must not
     * wait on the iteration's own locks).
     *
     * @param listener run after the commit, on the committing thread
     */
    public void onCommit(Runnable listener) {
        commitListeners.add(listener);
    }

    /** The next iteration commits with the group's others ({@link CommitGroup#add}). */
    void join(CommitGroup g) {
        if (shared != null) {
            throw new IllegalStateException("an iteration transaction is already open");
        }
        group = g;
    }

    /** The group ended without this transaction's iteration: the next one commits alone. */
    void leave(CommitGroup g) {
        if (group == g && shared == null) {
            group = null;
        }
    }

    /** @return whether the pool's connections take multi-statements, or null before the first iteration */
    Boolean multiStatements() {
        return multiStatements;
    }

    /** @return whether START TRANSACTION was sent for the open iteration (in a group: by any of its iterations) */
    private boolean transactionOpen() {
        return group != null ? group.serverTransaction() : serverTransaction;
    }

    private void transactionOpen(boolean open) {
        if (group != null) {
            group.serverTransaction(open);
        } else {
            serverTransaction = open;
        }
    }

    /**
     * Registers work to run at {@link #commit()}, before the commit itself, on the iteration's
     * thread, in the order registered (writes buffered during the iteration go as batches).
     *
     * @param work run once per committing iteration; its failure fails the commit
     */
    public void beforeCommit(BeforeCommit work) {
        beforeCommit.add(work);
    }

    /**
     * Opens the iteration's transaction on the calling thread.
     *
     * @throws StateStoreException when the database cannot be reached: the iteration must not
     *         run, since nothing of it could be saved
     */
    public void begin() {
        if (shared != null) {
            throw new IllegalStateException("an iteration transaction is already open");
        }
        Connection c = null;
        try {
            c = group != null ? group.connection() : null;
            if (c == null) {
                group = null; // no group, or one that cannot take this iteration: it commits alone
                c = pool.getConnection();
            }
            if (multiStatements == null) {
                multiStatements = RoundTrip.allowed(c);
            }
            if (!multiStatements) {
                c.setAutoCommit(false);
            }
        } catch (SQLException e) {
            if (group == null) {
                closeQuietly(c);
            } else {
                group.fail(); // the group's connection is the group's to end
                group = null;
            }
            throw new StateStoreException("cannot open the iteration's transaction: " + e.getMessage(), e);
        }
        shared = c;
        serverTransaction = false;
        deferred = multiStatements ? new RoundTrip() : null;
        writes = deferred != null ? deferred : Writes.atOnce(c);
        owner = Thread.currentThread();
        rollbackOnly = false;
        number++;
    }

    /**
     * @return the open iteration's connection, in its transaction, when called on the iteration's
     *         thread, else null (run the statement on a pooled connection of its own). Never
     *         commit or close it.
     * @throws StateStoreException when the transaction cannot be opened on the server
     */
    public Connection connection() {
        Connection c = readConnection();
        if (c != null && multiStatements && !transactionOpen()) {
            transactionOpen(true); // set first: a failure below still ends in ROLLBACK
            try {
                execute(c, opening());
            } catch (SQLException e) {
                rollbackOnly = true;
                throw new StateStoreException("cannot open the iteration's transaction: " + e.getMessage(), e);
            }
        }
        return c;
    }

    /**
     * @return the open iteration's connection for reads when called on the iteration's thread,
     *         else null; it sees the iteration's own writes. Never write on it (use
     *         {@link #connection()}, {@link #sendNow} or {@link #writes()}), commit or close it.
     */
    public Connection readConnection() {
        Connection c = shared;
        return c != null && Thread.currentThread() == owner ? c : null;
    }

    /**
     * Runs one write at once in the iteration's transaction (when the iteration's later reads or
     * other connections' rows depend on its order); on MariaDB and MySQL the first such write opens
     * the transaction in its own round trip.
     *
     * @param statement  one SQL statement, without a semicolon
     * @param parameters how many '?' it has
     * @param binder     binds them
     * @return its update count
     * @throws SQLException when it fails
     * @throws IllegalStateException when called outside the iteration's thread
     */
    public int sendNow(String statement, int parameters, Writes.Binder binder) throws SQLException {
        Connection c = readConnection();
        if (c == null) {
            throw new IllegalStateException("no iteration is open on this thread");
        }
        if (!multiStatements || transactionOpen()) {
            try (PreparedStatement ps = c.prepareStatement(statement)) {
                binder.bind(ps, 1);
                return ps.executeUpdate();
            } catch (SQLException e) {
                transactionMayBeGone(e);
                throw e;
            }
        }
        String opening = opening();
        transactionOpen(true); // set first: a failure below still ends in ROLLBACK
        try (PreparedStatement ps = c.prepareStatement(opening + ";\n" + statement)) {
            binder.bind(ps, 1);
            ps.execute(); // the opening's results, then the statement's
            if (!opening.equals(START_TRANSACTION)) {
                ps.getMoreResults(); // ROLLBACK's
            }
            if (!ps.getMoreResults() && ps.getUpdateCount() >= 0) {
                int count = ps.getUpdateCount();
                ps.getMoreResults(); // no more: drained, so that an error is seen
                return count;
            }
            throw new SQLException("no update count for: " + statement);
        } catch (SQLException e) {
            transactionMayBeGone(e);
            throw e;
        }
    }

    /**
     * @return what opens the iteration's server transaction: after a failure, a ROLLBACK first, since
     *         START TRANSACTION alone would commit what a connection wrongly taken for lost still holds
     */
    private String opening() {
        return rollbackOnly ? ROLLBACK_THEN_START : START_TRANSACTION;
    }

    /**
     * A statement on the open iteration's connection failed (a read too): when the failure means the
     * server's transaction is gone, nothing of the iteration may commit. Call it from the thread
     * running the iteration; elsewhere it does nothing.
     *
     * @param e what the statement threw
     */
    public void statementFailed(SQLException e) {
        if (readConnection() != null) {
            transactionMayBeGone(e);
        }
    }

    /**
     * A deadlock (1213; a certification conflict on Galera too) rolls the server's whole transaction
     * back, a lock wait time-out (1205) may, and so does a lost connection, which a failover driver
     * (jdbc:mariadb:sequential://a,b,c) replaces under the same Connection with one to another
     * server: the iteration can no longer commit whole. It is marked so ({@link #commit()} then
     * fails), and the next write opens a new transaction, rolled back at the end, so that no later
     * write of the iteration runs on its own in auto-commit mode.
     */
    private void transactionMayBeGone(SQLException e) {
        int code = e.getErrorCode();
        boolean lost = connectionLost(e);
        if (code == ER_LOCK_DEADLOCK || code == ER_LOCK_WAIT_TIMEOUT || lost) {
            rollbackOnly = true;
            if ((code == ER_LOCK_DEADLOCK || lost) && multiStatements) {
                transactionOpen(false);
            }
        }
    }

    /** @return whether e (or a cause) says the connection to the server was lost or replaced */
    static boolean connectionLost(SQLException e) {
        for (Throwable t = e; t != null; t = t.getCause() == t ? null : t.getCause()) {
            if (t instanceof SQLTransientConnectionException || t instanceof SQLNonTransientConnectionException
                    || t instanceof SQLRecoverableException) {
                return true;
            }
            if (t instanceof SQLException s && s.getSQLState() != null
                    && (s.getSQLState().startsWith("08") || s.getSQLState().equals("25S03"))) {
                return true; // 08: connection exception; 25S03: MariaDB's driver reconnected, transaction lost
            }
        }
        return false;
    }

    /**
     * Where the open iteration's writes that nobody reads back go: on MariaDB and MySQL they are
     * sent with the commit, as one round trip; elsewhere (H2, where a statement costs no round
     * trip) they run at once on {@link #connection()}.
     *
     * @return the iteration's writes when called on its thread, else null
     */
    public Writes writes() {
        return readConnection() != null ? writes : null;
    }

    /** @return a number that changes with every {@link #begin()}: what a per-iteration cache is keyed by */
    public long iterationNumber() {
        return number;
    }

    /** A part of the iteration failed its own unit of work: nothing of the iteration will commit. */
    public void markRollbackOnly() {
        rollbackOnly = true;
    }

    private static void abortQuietly(Connection c) {
        try {
            c.abort(Runnable::run);
        } catch (SQLException | RuntimeException ignored) {
            // already failing: the pool discards a closed connection
        }
    }

    private static void closeQuietly(Connection c) {
        if (c != null) {
            try {
                c.close();
            } catch (SQLException ignored) {
                // already failing: the first error is the one reported
            }
        }
    }

    /**
     * Runs the before-commit work, commits the iteration and releases the connection; when a part
     * of it asked for a rollback, rolls it back instead and says so. In a {@link CommitGroup} it only
     * hands the iteration's writes to the group: the group's commit commits it (and runs the
     * {@link #onCommit} listeners) or rolls it back.
     *
     * @throws SQLException when a part asked for a rollback, or the before-commit work or the
     *         commit fails; nothing of the iteration is then in the database
     */
    public void commit() throws SQLException {
        Connection c = shared;
        if (c == null) {
            return;
        }
        if (rollbackOnly) {
            rollback();
            throw new SQLException("iteration rolled back: a part of it failed its unit of work");
        }
        try {
            for (BeforeCommit work : beforeCommit) {
                work.run();
            }
            if (rollbackOnly) { // a part failed meanwhile (a deadlock the work did not rethrow): the iteration is not whole
                throw new SQLException("iteration rolled back: a part of it failed its unit of work");
            }
            if (group != null) { // committed with the group's others, or rolled back with them (groupEnded)
                group.stage(this, deferred);
                owner = null; // done: its tables no longer buffer or read on the group's connection
                return;
            }
            if (!multiStatements) {
                c.commit();
            } else if (deferred.statements() > 0) {
                deferred.commit(c, !transactionOpen()); // the writes and COMMIT in one round trip, opening the transaction if need be
            } else if (transactionOpen()) {
                execute(c, "COMMIT");
            }
        } catch (SQLException | RuntimeException e) {
            rollback();
            throw e;
        }
        release(true);
    }

    /**
     * Rolls the iteration back and releases the connection. In a group: the iterations staged
     * before it roll back with it at the group's end (its statements may be in their transaction),
     * and those after it commit alone.
     */
    public void rollback() {
        Connection c = shared;
        if (group != null) {
            group.fail();
            release(false);
            return;
        }
        if (c != null) {
            try {
                if (!multiStatements) {
                    c.rollback();
                } else if (transactionOpen()) {
                    execute(c, "ROLLBACK");
                }
            } catch (SQLException e) {
                abortQuietly(c); // perhaps still in a transaction: never back to the pool so
            }
        }
        release(false);
    }

    /** The group this iteration was staged in committed, or rolled back. */
    void groupEnded(boolean committed) {
        release(committed);
    }

    private static void execute(Connection c, String sql) throws SQLException {
        try (Statement st = c.createStatement()) {
            st.execute(sql);
        }
    }

    private void release(boolean committed) {
        Connection c = shared;
        boolean grouped = group != null;
        shared = null;
        deferred = null;
        writes = null;
        owner = null;
        serverTransaction = false;
        group = null;
        if (c == null) {
            return;
        }
        try {
            if (!multiStatements && !grouped) {
                c.setAutoCommit(true);
            }
        } catch (SQLException e) {
            // closed below; the pool discards a broken connection
        } finally {
            if (!grouped) {
                closeQuietly(c); // a group gives its connection back itself
            }
            if (committed) {
                commitListeners.forEach(Runnable::run);
            } else {
                rollbackListeners.forEach(Runnable::run);
            }
        }
    }

    /** @return a pooled connection of its own, outside any iteration's transaction */
    @Override
    public Connection getConnection() throws SQLException {
        return pool.getConnection();
    }

    @Override
    public Connection getConnection(String username, String password) throws SQLException {
        return pool.getConnection(username, password);
    }

    @Override
    public PrintWriter getLogWriter() throws SQLException {
        return pool.getLogWriter();
    }

    @Override
    public void setLogWriter(PrintWriter out) throws SQLException {
        pool.setLogWriter(out);
    }

    @Override
    public void setLoginTimeout(int seconds) throws SQLException {
        pool.setLoginTimeout(seconds);
    }

    @Override
    public int getLoginTimeout() throws SQLException {
        return pool.getLoginTimeout();
    }

    @Override
    public Logger getParentLogger() throws SQLFeatureNotSupportedException {
        return pool.getParentLogger();
    }

    @Override
    public <T> T unwrap(Class<T> iface) throws SQLException {
        if (iface.isInstance(this)) {
            return iface.cast(this);
        }
        return pool.unwrap(iface);
    }

    @Override
    public boolean isWrapperFor(Class<?> iface) throws SQLException {
        return iface.isInstance(this) || pool.isWrapperFor(iface);
    }
}
