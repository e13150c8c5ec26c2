package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Opens fresh test databases. H2 is always there; MariaDB only when the environment variable
 * {@value #MARIADB_URL_VARIABLE} holds a JDBC URL of a server where the user may create
 * databases (CI sets it). Without it, MariaDB cases are skipped with a message saying so, and one WARN
 * line per JVM says it on the console too (a skip's reason is otherwise only in the surefire XML).
 *
 * <pre>{@code
 * @ParameterizedTest @EnumSource(DatabaseKind.class)
 * void saves(DatabaseKind kind) throws Exception {
 *     try (TestDatabase db = TestDatabases.open(kind)) { ... db.dataSource() ... }
 * }
 * }</pre>
 */
public final class TestDatabases {

    /** The environment variable that names the MariaDB test server. */
    public static final String MARIADB_URL_VARIABLE = "PROACTIVE_TEST_MARIADB_URL";

    private static final String HOW = "set " + MARIADB_URL_VARIABLE
            + " (e.g. jdbc:mariadb://127.0.0.1:3306/proactive_test?user=root&password=) to run them";
    private static final SkipNotice SKIP_NOTICE = new SkipNotice(LoggerFactory.getLogger(TestDatabases.class));

    private static final Pattern URL = Pattern.compile("(jdbc:(?:mariadb|mysql)://[^/?]+)/([^?]*)(\\?.*)?");

    private TestDatabases() {
    }

    /**
     * Opens a fresh, empty database with the schema applied.
     *
     * @param kind which database
     * @return the database; close it at the end of the test
     */
    public static TestDatabase open(DatabaseKind kind) throws SQLException {
        String unique = "t" + UUID.randomUUID().toString().replace("-", "").substring(0, 12);
        return switch (kind) {
            case H2 -> new TestDatabase(kind, Databases.embeddedH2Url(unique), "sa", "", () -> dropH2(unique));
            case MARIADB -> openMariaDb(unique);
        };
    }

    /** @return the MariaDB test URL, or null (with one WARN per JVM) when none is configured */
    public static String mariaDbUrl() {
        String url = System.getenv(MARIADB_URL_VARIABLE);
        if (url == null || url.isBlank()) {
            SKIP_NOTICE.skipped();
            return null;
        }
        return url.trim();
    }

    private static TestDatabase openMariaDb(String unique) throws SQLException {
        String base = mariaDbUrl();
        Assumptions.assumeTrue(base != null, "MariaDB tests skipped: " + HOW);
        Matcher m = URL.matcher(base);
        if (!m.matches()) {
            throw new IllegalArgumentException(MARIADB_URL_VARIABLE + " is not a jdbc:mariadb:// or jdbc:mysql:// URL: " + base);
        }
        String server = m.group(1);
        String query = m.group(3) == null ? "" : m.group(3);
        String database = "proactive_" + unique;
        try (Connection c = DriverManager.getConnection(base); Statement s = c.createStatement()) {
            s.execute("CREATE DATABASE " + database);
        }
        String url = server + "/" + database + query;
        return new TestDatabase(DatabaseKind.MARIADB, url, null, null, () -> dropMariaDb(base, database));
    }

    private static void dropMariaDb(String base, String database) {
        try (Connection c = DriverManager.getConnection(base); Statement s = c.createStatement()) {
            s.execute("DROP DATABASE IF EXISTS " + database);
        } catch (SQLException e) {
            throw new IllegalStateException("could not drop test database " + database, e);
        }
    }

    /** Says once, on the console, that the MariaDB tests are skipped and how to run them. */
    static final class SkipNotice {
        private final Logger log;
        private final AtomicBoolean said = new AtomicBoolean();

        SkipNotice(Logger log) {
            this.log = log;
        }

        /** A MariaDB test is being skipped: the first time, say why. */
        void skipped() {
            if (said.compareAndSet(false, true)) {
                log.warn("MariaDB tests skipped in this JVM: {}", HOW);
            }
        }
    }

    private static void dropH2(String name) {
        try (Connection c = DriverManager.getConnection(Databases.embeddedH2Url(name), "sa", "");
             Statement s = c.createStatement()) {
            s.execute("DROP ALL OBJECTS");
            s.execute("SHUTDOWN");
        } catch (SQLException e) {
            throw new IllegalStateException("could not drop H2 test database " + name, e);
        }
    }
}
