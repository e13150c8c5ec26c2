package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Waits for the shared database with exponential back-off: until a connection opens as the
 * given user and a table of the schema can be read. Each failed attempt is one status line with
 * the reason, never a stack trace: a database that is not up yet is expected. A cause waiting
 * cannot cure (access denied, unknown database; see {@link DatabaseProblem.Cause}) ends the wait
 * at once.
 */
public final class DatabaseWait {

    private static final Logger LOG = LoggerFactory.getLogger(DatabaseWait.class);
    private static final long FIRST_DELAY_MS = 500;
    private static final long MAX_DELAY_MS = 8_000;

    /** The database did not become usable in time; the message says why and what to do. */
    public static final class Unreachable extends Exception {
        private static final long serialVersionUID = 1L;

        private final transient DatabaseProblem problem;

        Unreachable(DatabaseProblem problem, String message) {
            super(message);
            this.problem = problem;
        }

        /** @return the last problem seen */
        public DatabaseProblem problem() {
            return problem;
        }
    }

    private DatabaseWait() {
    }

    /**
     * @param db    where and as whom
     * @param table a table of the schema this side reads (proves the schema and the grants), or
     *              null to need only a connection
     * @param stop  true when the process is asked to stop (ends the wait)
     * @return true once usable, false when stopped first
     * @throws Unreachable when not usable within {@link DbOptions#waitS()}, or at once for a
     *                     cause waiting cannot cure
     */
    public static boolean await(DbOptions db, String table, BooleanSupplier stop) throws Unreachable {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(db.waitS());
        long delayMs = FIRST_DELAY_MS;
        for (int attempt = 1; ; attempt++) {
            DatabaseProblem problem = probe(db, table);
            if (problem == null) {
                if (attempt > 1) {
                    LOG.info("database is up (attempt {})", attempt);
                }
                return true;
            }
            if (!problem.worthWaiting()) {
                throw new Unreachable(problem, problem.message());
            }
            long leftMs = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (leftMs <= 0) {
                throw new Unreachable(problem, "database not usable within " + db.waitS() + " s (--wait-s, " + attempt
                        + (attempt == 1 ? " attempt): " : " attempts): ") + problem.message());
            }
            long sleepMs = Math.min(delayMs, leftMs);
            String line = "waiting for the database (attempt {}, retrying in {} s, giving up after {} s): {}";
            Object[] args = {attempt, String.format(Locale.ROOT, "%.1f", sleepMs / 1000.0), db.waitS(), problem.message()};
            if (attempt == 1) {
                LOG.warn(line, args); // shown by the one-shot commands too, whose log level is WARN
            } else {
                LOG.info(line, args);
            }
            long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(sleepMs);
            while (System.nanoTime() - until < 0) {
                if (stop.getAsBoolean()) {
                    return false;
                }
                sleep(Math.min(100, TimeUnit.NANOSECONDS.toMillis(until - System.nanoTime()) + 1));
            }
            delayMs = Math.min(MAX_DELAY_MS, delayMs * 2);
        }
    }

    /** @return null when the database is usable, else what is wrong */
    static DatabaseProblem probe(DbOptions db, String table) {
        String folder = H2Folder.problem(db.url());
        if (folder != null) { // before H2 tries: it would print a stack trace of its own
            return DatabaseProblem.noFolder(folder);
        }
        try (Connection c = db.connect(); Statement s = c.createStatement()) {
            s.executeQuery(table == null ? "SELECT 1" : "SELECT COUNT(*) FROM " + table + " WHERE 1 = 0").close();
            return null;
        } catch (SQLException e) {
            return DatabaseProblem.of(e, db.url(), table);
        }
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(Math.max(1, ms));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
