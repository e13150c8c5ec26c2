package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.Locale;
import java.util.regex.Pattern;
import javax.sql.DataSource;

/**
 * Wake-ups for one side of the synchronous handshake on MariaDB: the side that waits for the
 * other blocks in the server on a named lock ({@code GET_LOCK}) that the other side holds, and
 * wakes when that side releases it after committing its step, instead of polling the clock
 * tables. The clock tables stay the truth: a wake-up is only a hint to read them now. A wait that
 * ends without the step (the other side gone, or not using the locks) leaves the rest of that
 * step to polling, and one that times out (the other side is slow) is made again; when waits
 * keep finding nothing, or keep timing out though the step is there, the side polls for a while
 * ({@link #found}).
 *
 * <p>The handshake's steps are numbered signals: the robot's "sensed step k" is signal
 * {@link #sensed 2k}, the engine's "served step k" is signal {@link #served 2k + 1}. Signal n is
 * given by releasing lock n mod 3, and awaited by acquiring it; the waiting side keeps the lock
 * it woke on and gives the signal n + 3 with it. With three locks in rotation, the lock a side
 * waits on is always one the other side acquired before its previous signal, so a side never
 * takes back the lock it has just released before the other side got it (with two locks it could).
 *
 * <p>A lock belongs to a database session, so this keeps one connection of its own for as long
 * as it is used; any failure releases every lock held and gives the connection back (the other
 * side then stops waiting and polls). Not thread-safe: one per robot per side.
 */
public final class HandshakeLocks implements AutoCloseable {

    /** Reads what the exchange's query returned. */
    @FunctionalInterface
    public interface Reader<T> {
        /**
         * @param rs the result of the exchange's query
         * @return what it says
         */
        T read(ResultSet rs) throws SQLException;
    }

    /** The wait for one exchange, as the server saw it. */
    public enum Wake {
        /** The lock was acquired (the other side released it, or nobody held it). */
        ACQUIRED,
        /** The wait timed out: the other side still holds the lock. */
        TIMED_OUT,
        /** No wait: this side already held the lock (an earlier exchange acquired it). */
        HELD
    }

    /** Useless waits in a row before a side stops waiting in the server for a while (one or two happen as the rotation starts). */
    private static final int MISSES_TO_PAUSE = 4;
    /** How long a side then polls instead, ns. */
    private static final long PAUSE_NANOS = 5_000_000_000L;

    /** What MariaDB answers a GET_LOCK that would close a cycle of waits. */
    private static final int ER_LOCK_DEADLOCK = 1213;

    private static final Pattern PLAIN = Pattern.compile("[A-Za-z0-9_$-]{1,24}");
    /** MySQL's and MariaDB's error for a variable the server does not have. */
    private static final int ER_UNKNOWN_SYSTEM_VARIABLE = 1193;

    private final DataSource dataSource;
    private final int robotId;
    private final String[] names = new String[3];
    private final boolean[] held = new boolean[3];
    private Boolean supported;
    private Connection connection;
    private Wake lastWake;
    private int misses;
    private long pausedUntilNanos = System.nanoTime();
    /** How many exchanges' waits ended each way, by {@link Wake#ordinal()}. */
    private final long[] wakes = new long[3];

    /**
     * Opens nothing yet: the first {@link #usable()} asks the database.
     *
     * @param dataSource the shared database (one connection is kept from it while the locks are used)
     * @param robotId    the robot whose handshake this is
     */
    public HandshakeLocks(DataSource dataSource, int robotId) {
        this.dataSource = dataSource;
        this.robotId = robotId;
    }

    /**
     * A Galera node's locks are its own (GET_LOCK is not replicated): an engine and a robot on two
     * nodes would each take their lock at once, so the handshake polls instead.
     */
    private static boolean isGalera(Connection c) throws SQLException {
        try (Statement st = c.createStatement(); ResultSet rs = st.executeQuery("SELECT @@wsrep_on")) {
            return rs.next() && rs.getInt(1) == 1;
        } catch (SQLException e) {
            if (e.getErrorCode() == ER_UNKNOWN_SYSTEM_VARIABLE) {
                return false; // a server built without Galera
            }
            throw e;
        }
    }

    /** @return the signal of the robot's "sensed step k" */
    public static long sensed(long step) {
        return 2 * step;
    }

    /** @return the signal of the engine's "served step k" */
    public static long served(long step) {
        return 2 * step + 1;
    }

    /** @return the robot whose handshake this is */
    public int robotId() {
        return robotId;
    }

    /**
     * Whether the database can wait this way: MariaDB (fractional lock time-outs) with
     * multi-statements allowed. MySQL is not used: its {@code GET_LOCK} time-out is whole seconds.
     *
     * @return true when {@link #exchange} may be called
     * @throws SQLException when the database could not be asked (it is asked again next time)
     */
    public boolean usable() throws SQLException {
        if (supported == null) {
            Connection c = dataSource.getConnection();
            boolean ok = false;
            try {
                ok = c.getMetaData().getDatabaseProductVersion().toLowerCase(Locale.ROOT).contains("mariadb")
                        && RoundTrip.allowed(c) && !isGalera(c);
                if (ok) {
                    String catalog = c.getCatalog() == null ? "" : c.getCatalog();
                    String db = PLAIN.matcher(catalog).matches() ? catalog : Integer.toHexString(catalog.hashCode());
                    for (int k = 0; k < 3; k++) {
                        names[k] = "proactive/" + db + "/robot/" + robotId + "/" + k; // at most 64 characters
                    }
                    connection = c;
                }
                supported = ok;
            } finally {
                if (!ok) {
                    c.close();
                }
            }
        }
        return supported;
    }

    /**
     * Gives one signal and awaits another, then runs a query, all in one round trip:
     * {@code DO RELEASE_LOCK(given); SELECT GET_LOCK(awaited, timeout); query}. The release is
     * skipped when this side does not hold the given signal's lock, the wait when it already holds
     * the awaited one.
     *
     * @param given         the signal this side gives now (its step is committed), or -1 for none
     * @param awaited       the signal of the other side this side waits for
     * @param timeoutNanos  the longest wait in the server, ns
     * @param query         a query (with ? parameters) run once the wait ends
     * @param binder        binds the query's parameters from 1
     * @param reader        reads its result
     * @return what the reader read
     * @throws SQLException when the round trip failed: the connection is closed, every lock released
     */
    public <T> T exchange(long given, long awaited, long timeoutNanos, String query, Writes.Binder binder, Reader<T> reader)
            throws SQLException {
        if (!usable()) {
            throw new IllegalStateException("this database cannot wait on locks: check usable() first");
        }
        try {
            if (connection == null) {
                connection = dataSource.getConnection();
            }
            int give = given < 0 ? -1 : (int) (given % 3);
            boolean release = give >= 0 && held[give];
            int await = (int) (awaited % 3);
            boolean wait = !held[await];
            StringBuilder sql = new StringBuilder(160);
            if (release) {
                sql.append("DO RELEASE_LOCK('").append(names[give]).append("');\n");
            }
            if (wait) {
                sql.append("SELECT GET_LOCK('").append(names[await]).append("', ")
                        .append(String.format(Locale.ROOT, "%.6f", timeoutNanos / 1e9)).append(");\n");
            }
            sql.append(query);
            try (PreparedStatement ps = connection.prepareStatement(sql.toString())) {
                binder.bind(ps, 1);
                boolean resultSet = ps.execute();
                if (release) {
                    held[give] = false;
                    resultSet = ps.getMoreResults();
                }
                if (wait) {
                    try (ResultSet rs = ps.getResultSet()) {
                        rs.next();
                        held[await] = rs.getInt(1) == 1; // 0: timed out; NULL (0 here): the wait was killed
                    }
                    lastWake = held[await] ? Wake.ACQUIRED : Wake.TIMED_OUT;
                    resultSet = ps.getMoreResults();
                } else {
                    lastWake = Wake.HELD;
                }
                if (!resultSet) {
                    throw new SQLException("the exchange's query returned no rows: " + query);
                }
                wakes[lastWake.ordinal()]++;
                try (ResultSet rs = ps.getResultSet()) {
                    return reader.read(rs);
                }
            }
        } catch (SQLException e) {
            close();
            if (e.getErrorCode() != ER_LOCK_DEADLOCK) {
                throw e;
            }
            // a cycle with a session that is not the other side (their locks are never both awaited): as a time-out
            lastWake = Wake.TIMED_OUT;
            wakes[lastWake.ordinal()]++;
            try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(query)) {
                binder.bind(ps, 1);
                try (ResultSet rs = ps.executeQuery()) {
                    return reader.read(rs);
                }
            }
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /**
     * @param wake a way for a wait to end
     * @return how many exchanges' waits ended that way
     */
    public long count(Wake wake) {
        return wakes[wake.ordinal()];
    }

    /** @return how many exchanges waited on a lock (acquired or timed out; not those that held it already) */
    public long waits() {
        return count(Wake.ACQUIRED) + count(Wake.TIMED_OUT);
    }

    /**
     * Tells whether the last exchange's query found the step awaited. A lock acquired at once
     * without it, several times running, means that the other side does not use the locks (an
     * engine thread that serves several robots polls their clocks instead); a wait that timed
     * out though the step was there, that a session which is not the other side holds the lock
     * (a process that hung, or whose host was cut off, keeps its session until the server's
     * {@code wait_timeout}). Either way this side then lets go of its locks and polls for
     * {@value #PAUSE_NANOS} ns before it tries again.
     *
     * @param found whether the other side's step was there
     */
    public void found(boolean found) {
        // a lock acquired at once without the step: the other side does not hold them; a time-out with
        // the step there: a session that is not the other side holds one (a hung or cut-off process)
        boolean miss = lastWake == Wake.ACQUIRED && !found || lastWake == Wake.TIMED_OUT && found;
        if (lastWake == Wake.ACQUIRED && found) {
            misses = 0;
        } else if (miss && ++misses >= MISSES_TO_PAUSE) {
            misses = MISSES_TO_PAUSE - 2; // after the pause, two more misses pause again
            pausedUntilNanos = System.nanoTime() + PAUSE_NANOS;
            close();
        }
    }

    /** @return whether this side should poll instead of waiting in the server for now ({@link #found}) */
    public boolean paused() {
        return System.nanoTime() - pausedUntilNanos < 0;
    }

    /** @return how the last exchange's wait ended, or null before the first */
    public Wake lastWake() {
        return lastWake;
    }

    /**
     * Releases every lock held and gives the connection back (the next exchange takes another).
     * A pooled connection outlives its {@code close()}, and its locks with it, hence the release;
     * when even that fails, the connection is aborted, which ends its session.
     */
    @Override
    public void close() {
        java.util.Arrays.fill(held, false);
        Connection c = connection;
        connection = null;
        if (c == null) {
            return;
        }
        try (java.sql.Statement s = c.createStatement()) {
            s.execute("DO RELEASE_ALL_LOCKS()");
        } catch (SQLException | RuntimeException e) {
            try {
                c.abort(Runnable::run); // a session that may still hold locks must not go back to the pool
            } catch (SQLException | RuntimeException ignored) {
                // already broken: its session, and its locks, are gone with it
            }
            return;
        }
        try {
            c.close();
        } catch (SQLException e) {
            // released already: nothing is held whatever happens to the connection
        }
    }

    /** @return whether any lock is held */
    public boolean holdsAny() {
        return held[0] || held[1] || held[2];
    }
}
