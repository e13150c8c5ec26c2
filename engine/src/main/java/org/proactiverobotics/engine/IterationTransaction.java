package org.proactiverobotics.engine;

import java.io.PrintWriter;
import java.sql.Connection;
import java.sql.SQLException;
import java.sql.SQLFeatureNotSupportedException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Logger;
import javax.sql.DataSource;
import org.proactiverobotics.db.RoundTrip;
import org.proactiverobotics.db.Writes;

/**
 * One database transaction per engine iteration, on one explicit connection: between
 * {@link #begin()} and {@link #commit()} the iteration's thread gets that connection from
 * {@link #connection()} and runs its statements on it without committing or closing it. The
 * rules' tables and the {@link JdbcStateStore} do so: an iteration's writes (commands, requests,
 * marks, buffered until {@link #commit()} by whoever registered {@link #beforeCommit}) and its
 * saved state then commit together, once — all of an iteration or none of it survives a crash,
 * and a server that flushes its log at every commit does so once per iteration.
 * {@link #getConnection()} is always the plain pool (outside the iteration's transaction).
 */
public final class IterationTransaction implements DataSource {

    /** Work run on the iteration's connection just before it commits (buffered writes). */
    @FunctionalInterface
    public interface BeforeCommit {
        /** @param c the iteration's connection, in its transaction */
        void run(Connection c) throws SQLException;
    }

    private final DataSource pool;
    private final List<Runnable> rollbackListeners = new CopyOnWriteArrayList<>();
    private final List<BeforeCommit> beforeCommit = new CopyOnWriteArrayList<>();
    private Connection shared;
    /** Whether the pool's connections take multi-statements (MariaDB, MySQL); null until the first iteration. */
    private Boolean multiStatements;
    /** The open iteration's writes that are sent with its commit, or null (they run at once instead). */
    private RoundTrip deferred;
    /** Where the open iteration's writes go: {@link #deferred}, or its connection at once. */
    private Writes writes;
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
     * Registers work to run on the iteration's connection at {@link #commit()}, before the commit
     * itself, in the order registered (writes buffered during the iteration go as batches).
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
            c = pool.getConnection();
            c.setAutoCommit(false);
            if (multiStatements == null) {
                multiStatements = RoundTrip.allowed(c);
            }
        } catch (SQLException e) {
            closeQuietly(c);
            throw new StateStoreException("cannot open the iteration's transaction: " + e.getMessage(), e);
        }
        shared = c;
        deferred = multiStatements ? RoundTrip.endingTransaction() : null;
        writes = deferred != null ? deferred : Writes.atOnce(c);
        owner = Thread.currentThread();
        rollbackOnly = false;
        number++;
    }

    /**
     * @return the open iteration's connection when called on the iteration's thread, else null
     *         (run the statement on a pooled connection of its own). Never commit or close it.
     */
    public Connection connection() {
        Connection c = shared;
        return c != null && Thread.currentThread() == owner ? c : null;
    }

    /**
     * Where the open iteration's writes that nobody reads back go: on MariaDB and MySQL they are
     * sent with the commit, as one round trip; elsewhere (H2, where a statement costs no round
     * trip) they run at once on {@link #connection()}.
     *
     * @return the iteration's writes when called on its thread, else null
     */
    public Writes writes() {
        return connection() != null ? writes : null;
    }

    /** @return a number that changes with every {@link #begin()}: what a per-iteration cache is keyed by */
    public long iterationNumber() {
        return number;
    }

    /** A part of the iteration failed its own unit of work: nothing of the iteration will commit. */
    public void markRollbackOnly() {
        rollbackOnly = true;
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
     * Runs the before-commit work, commits the iteration (or rolls it back when a part of it
     * asked to) and releases the connection.
     *
     * @throws SQLException when the before-commit work or the commit fails; the iteration's
     *         writes are then lost
     */
    public void commit() throws SQLException {
        Connection c = shared;
        if (c != null && !rollbackOnly) {
            try {
                for (BeforeCommit work : beforeCommit) {
                    work.run(c);
                }
                RoundTrip trip = deferred;
                deferred = null;
                if (trip != null && trip.statements() > 0) {
                    trip.commit(c); // the writes and COMMIT in one round trip; the driver's commit below then sends nothing
                }
            } catch (SQLException | RuntimeException e) {
                rollback();
                throw e;
            }
        }
        end(!rollbackOnly);
    }

    /** Rolls the iteration back and releases the connection. */
    public void rollback() {
        try {
            end(false);
        } catch (SQLException e) {
            // the connection is being discarded anyway
        }
    }

    private void end(boolean commit) throws SQLException {
        Connection c = shared;
        shared = null;
        deferred = null;
        writes = null;
        owner = null;
        if (c == null) {
            return;
        }
        boolean committed = false;
        try {
            if (commit) {
                c.commit();
                committed = true;
            } else {
                c.rollback();
            }
        } finally {
            try {
                c.setAutoCommit(true);
            } finally {
                c.close();
                if (!committed) {
                    rollbackListeners.forEach(Runnable::run);
                }
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
