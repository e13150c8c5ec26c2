package org.proactiverobotics.engine;

import java.io.PrintWriter;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.sql.Connection;
import java.sql.SQLException;
import java.sql.SQLFeatureNotSupportedException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Logger;
import javax.sql.DataSource;

/**
 * One database transaction per engine iteration: a {@link DataSource} that, between
 * {@link #begin()} and {@link #commit()}, hands the iteration's thread one shared connection
 * whose own commit, rollback and close are deferred to the iteration's end. Give it to the
 * rules' tables and to the {@link JdbcStateStore}: an iteration's writes (commands, requests,
 * marks) and its saved state then commit together, once — all of an iteration or none of it
 * survives a crash, and a server that flushes its log at every commit does so once per
 * iteration. Outside an iteration, and on other threads, it is the plain pool.
 */
public final class IterationTransaction implements DataSource {

    private final DataSource pool;
    private final List<Runnable> rollbackListeners = new CopyOnWriteArrayList<>();
    private Connection shared;
    private Thread owner;
    private boolean rollbackOnly;

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
        } catch (SQLException e) {
            closeQuietly(c);
            throw new StateStoreException("cannot open the iteration's transaction: " + e.getMessage(), e);
        }
        shared = c;
        owner = Thread.currentThread();
        rollbackOnly = false;
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
     * Commits the iteration (or rolls it back when a part of it asked to) and releases the
     * connection.
     *
     * @throws SQLException when the commit fails; the iteration's writes are then lost
     */
    public void commit() throws SQLException {
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

    @Override
    public Connection getConnection() throws SQLException {
        Connection c = shared;
        if (c != null && Thread.currentThread() == owner) {
            return (Connection) Proxy.newProxyInstance(Connection.class.getClassLoader(),
                    new Class<?>[] {Connection.class}, new Deferring(c));
        }
        return pool.getConnection();
    }

    @Override
    public Connection getConnection(String username, String password) throws SQLException {
        return pool.getConnection(username, password);
    }

    /** Passes everything to the shared connection but what would end its transaction. */
    private final class Deferring implements InvocationHandler {
        private final Connection target;

        Deferring(Connection target) {
            this.target = target;
        }

        @Override
        public Object invoke(Object proxy, Method method, Object[] args) throws Throwable {
            switch (method.getName()) {
                case "close", "commit", "setAutoCommit":
                    return null;
                case "rollback":
                    if (args == null) {
                        rollbackOnly = true; // a part of the iteration failed its own unit: none of it commits
                        return null;
                    }
                    break;
                case "getAutoCommit":
                    return false;
                case "isClosed":
                    return shared != target;
                case "unwrap":
                    if (args[0] == Connection.class) {
                        return target;
                    }
                    break;
                default:
                    break;
            }
            try {
                return method.invoke(target, args);
            } catch (InvocationTargetException e) {
                throw e.getCause();
            }
        }
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
