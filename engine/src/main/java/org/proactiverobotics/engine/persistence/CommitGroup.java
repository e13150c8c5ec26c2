package org.proactiverobotics.engine.persistence;

import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import javax.sql.DataSource;
import org.proactiverobotics.db.RoundTrip;

/**
 * The iterations of several robots that one thread runs one after the other, committed as one
 * transaction in one round trip on MariaDB or MySQL: a server's commit costs more than most of an
 * iteration's statements (0.35 ms of a robot-step's 1.6 ms with 8 robots, slow log), and this
 * pays it once for all of them. Each iteration's {@link IterationTransaction} joins the group
 * ({@link #add}) before it begins; its {@link IterationTransaction#commit()} then only hands its
 * writes over, and {@link #commit()} sends them all with {@code COMMIT}. When one iteration fails,
 * it and those that ran before it in the group roll back (their rollback listeners run; each
 * engine resumes from its saved state at its next iteration) and those after it commit alone; when
 * the group's commit fails, every iteration it held rolls back. Where the server does not take
 * multi-statements (H2) the iterations commit one by one, as without a group. Not thread-safe: one
 * thread runs it.
 */
public final class CommitGroup implements AutoCloseable {

    private final DataSource pool;
    private final List<IterationTransaction> members = new ArrayList<>();
    private final List<IterationTransaction> staged = new ArrayList<>();
    /** The iterations that ran to their end in the group but did not commit with it. */
    private final List<IterationTransaction> rolledBack = new ArrayList<>();
    private final RoundTrip writes = new RoundTrip();
    private Connection connection;
    /** Whether the pool's connections take multi-statements; null until a member or the connection tells. */
    private Boolean multiStatements;
    /** START TRANSACTION was sent on the group's connection (by any member, or the group's commit). */
    private boolean serverTransaction;
    private boolean failed;
    private boolean ended;

    /** @param pool the connection pool the iterations' transactions use */
    public CommitGroup(DataSource pool) {
        this.pool = pool;
    }

    /**
     * Makes the next iteration of this transaction one of the group's.
     *
     * @param transaction an engine's iteration transaction over the same database, not open
     */
    public void add(IterationTransaction transaction) {
        transaction.join(this);
        members.add(transaction);
        if (multiStatements == null) {
            multiStatements = transaction.multiStatements(); // known after its first iteration: no need to ask the server
        }
    }

    /**
     * @return the group's connection, borrowed at the first iteration; null when the iterations
     *         are to commit one by one (the server takes no multi-statements, or an iteration of
     *         the group failed already and the others must not join its rolled-back transaction)
     * @throws SQLException when no connection can be had
     */
    Connection connection() throws SQLException {
        if (failed || ended || Boolean.FALSE.equals(multiStatements)) {
            return null;
        }
        if (connection == null) {
            Connection c = pool.getConnection();
            try {
                if (multiStatements == null) {
                    multiStatements = RoundTrip.allowed(c);
                }
            } catch (SQLException | RuntimeException e) {
                c.close();
                throw e;
            }
            if (!multiStatements) {
                c.close();
                return null;
            }
            connection = c;
        }
        return connection;
    }

    /** @return whether START TRANSACTION was sent on the group's connection */
    boolean serverTransaction() {
        return serverTransaction;
    }

    /** @param open whether a transaction is open on the group's connection now */
    void serverTransaction(boolean open) {
        serverTransaction = open;
    }

    /** An iteration of the group is done: its writes go with the group's commit. */
    void stage(IterationTransaction transaction, RoundTrip kept) {
        writes.addAll(kept);
        staged.add(transaction);
    }

    /** An iteration of the group failed (it says so itself): those staged before it will not commit, and none joins after. */
    void fail() {
        failed = true;
    }

    /**
     * Commits every iteration the group holds, in one round trip.
     *
     * @throws SQLException when an iteration of the group failed, or the commit did: the
     *         iterations staged in the group are not in the database then (after an I/O error the
     *         server's outcome is not known: the engines resume from what they find saved);
     *         {@link #rolledBack()} says which
     */
    public void commit() throws SQLException {
        if (ended) {
            return;
        }
        ended = true;
        SQLException failure = null;
        if (failed) {
            failure = new SQLException("a robot's iteration failed: the iterations run before it in its batch rolled back");
        } else if (connection != null) {
            try {
                if (writes.statements() > 0) {
                    boolean opening = !serverTransaction;
                    serverTransaction = true; // set first: when the round trip fails, ROLLBACK (or an abort) follows
                    writes.commit(connection, opening);
                    serverTransaction = false;
                } else if (serverTransaction) {
                    execute(connection, "COMMIT");
                    serverTransaction = false;
                }
            } catch (SQLException e) {
                failure = e;
            }
        }
        if (failure != null) {
            rollbackServer(failure);
        }
        end(failure == null);
        if (failure != null) {
            throw failure;
        }
    }

    /**
     * @return the iterations that ran to their end in the group but did not commit with it (after
     *         {@link #commit()} or {@link #close()}), in the order they ran; an iteration that failed
     *         itself is not among them (its own commit or rollback said so)
     */
    public List<IterationTransaction> rolledBack() {
        return List.copyOf(rolledBack);
    }

    /** Rolls back whatever was not committed and gives the connection back. */
    @Override
    public void close() {
        if (!ended) {
            ended = true;
            rollbackServer(null);
            end(false);
        }
    }

    private void rollbackServer(Exception cause) {
        if (connection != null && serverTransaction) {
            try {
                execute(connection, "ROLLBACK");
            } catch (SQLException e) {
                if (cause != null) {
                    cause.addSuppressed(e);
                }
                try {
                    connection.abort(Runnable::run); // perhaps still in a transaction: never back to the pool so
                } catch (SQLException | RuntimeException ignored) {
                    // the pool discards a closed connection
                }
            }
        }
        serverTransaction = false;
    }

    /** Gives the connection back, then tells every staged iteration how it ended (each, even when one's listener throws). */
    private void end(boolean committed) {
        List<IterationTransaction> all = List.copyOf(staged);
        staged.clear();
        if (!committed) {
            rolledBack.addAll(all);
        }
        try {
            if (connection != null) {
                connection.close();
            }
        } catch (SQLException ignored) {
            // the pool discards a broken connection
        }
        connection = null;
        RuntimeException first = null;
        for (IterationTransaction t : all) {
            try {
                t.groupEnded(committed);
            } catch (RuntimeException e) {
                first = first == null ? e : first;
            }
        }
        members.forEach(t -> t.leave(this)); // those whose iteration did not run commit alone next time
        members.clear();
        if (first != null) {
            throw first;
        }
    }

    private static void execute(Connection c, String sql) throws SQLException {
        try (Statement st = c.createStatement()) {
            st.execute(sql);
        }
    }
}
