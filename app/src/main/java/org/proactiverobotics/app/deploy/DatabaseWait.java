package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Waits for the shared database with exponential back-off: until a connection opens as the
 * given user and a table of the schema can be read. Each failed attempt is one INFO status line
 * with the reason, never a stack trace: a database that is not up yet is expected.
 */
public final class DatabaseWait {

    private static final Logger LOG = LoggerFactory.getLogger(DatabaseWait.class);
    private static final long FIRST_DELAY_MS = 500;
    private static final long MAX_DELAY_MS = 8_000;

    /** The database did not become usable in time; the message says why. */
    public static final class Unreachable extends Exception {
        private static final long serialVersionUID = 1L;

        Unreachable(String message) {
            super(message);
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
     * @throws Unreachable when not usable within {@link DbOptions#waitS()}
     */
    public static boolean await(DbOptions db, String table, BooleanSupplier stop) throws Unreachable {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(db.waitS());
        long delayMs = FIRST_DELAY_MS;
        for (int attempt = 1; ; attempt++) {
            String problem = probe(db, table);
            if (problem == null) {
                if (attempt > 1) {
                    LOG.info("database is up (attempt {})", attempt);
                }
                return true;
            }
            long leftMs = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (leftMs <= 0) {
                throw new Unreachable("database not usable within " + db.waitS() + " s (" + attempt + " attempts): " + problem);
            }
            long sleepMs = Math.min(delayMs, leftMs);
            LOG.info("waiting for the database (attempt {}, retrying in {} s): {}", attempt,
                    String.format(Locale.ROOT, "%.1f", sleepMs / 1000.0), problem);
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

    /** @return null when the database is usable, else the reason in one line */
    static String probe(DbOptions db, String table) {
        Properties props = new Properties();
        if (db.user() != null) {
            props.setProperty("user", db.user());
        }
        if (db.password() != null) {
            props.setProperty("password", db.password());
        }
        if (db.url().startsWith("jdbc:mariadb:") || db.url().startsWith("jdbc:mysql:")) {
            props.setProperty("connectTimeout", "5000"); // ms, both drivers: an unreachable host must not hang an attempt
        }
        try (Connection c = DriverManager.getConnection(db.url(), props); Statement s = c.createStatement()) {
            s.executeQuery(table == null ? "SELECT 1" : "SELECT COUNT(*) FROM " + table + " WHERE 1 = 0").close();
            return null;
        } catch (SQLException e) {
            return reason(e, table);
        }
    }

    private static String reason(SQLException e, String table) {
        String state = e.getSQLState() == null ? "" : e.getSQLState();
        String message = firstLine(e.getMessage());
        if (state.equals("42S02") || state.equals("42S01") || state.startsWith("42S0") || message.contains("doesn't exist")
                || message.contains("not found")) {
            return "the schema is not applied yet (table " + table + " missing; `proactive db init` applies it): " + message;
        }
        if (state.equals("28000") || message.contains("Access denied")) {
            return "access denied (user not created yet, or a wrong password): " + message;
        }
        return message;
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "(no message)";
        }
        int nl = s.indexOf('\n');
        return (nl < 0 ? s : s.substring(0, nl)).strip();
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(Math.max(1, ms));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
