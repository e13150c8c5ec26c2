package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.util.Properties;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.proactiverobotics.db.Databases;
import picocli.CommandLine.Option;

/**
 * The database options the two-process commands share (a picocli mixin). The password may come
 * from the environment, so that it never shows in a process list.
 */
public final class DbOptions {

    /** A password given in a JDBC URL (MySQL/MariaDB ?password=, H2 ;PASSWORD=). */
    private static final Pattern PASSWORD_IN_URL = Pattern.compile("((?:^|[?&;:])password=)[^&;]*", Pattern.CASE_INSENSITIVE);

    /** The environment variable a password defaults to. */
    public static final String PASSWORD_VARIABLE = "PROACTIVE_DB_PASSWORD";

    /**
     * A MariaDB or MySQL URL: the server part (one host, or a list with the drivers' failover modes,
     * e.g. jdbc:mariadb:sequential://a:3306,b:3306), the database name, the parameters.
     */
    private static final Pattern SERVER_URL = Pattern.compile("(jdbc:(?:mariadb|mysql)(?::[a-z-]+)?://[^/?]+)(?:/([^?]*))?(\\?.*)?");

    @Option(names = "--db", paramLabel = "JDBC_URL", required = true,
            description = "The shared database, e.g. jdbc:mysql://mysql:3306/proactive or jdbc:mariadb://127.0.0.1:3306/proactive.")
    String url;

    @Option(names = "--db-user", paramLabel = "U", description = "Database user (default: from the URL).")
    String user;

    @Option(names = "--db-password", paramLabel = "P", defaultValue = "${env:" + PASSWORD_VARIABLE + "}",
            description = "Database password. Default: the environment variable " + PASSWORD_VARIABLE + ".")
    String password;

    @Option(names = "--wait-s", paramLabel = "S", defaultValue = "60",
            description = "How long to wait for a database server that is not up yet (connection refused, unknown host,"
                    + " schema missing) before giving up (exit 3); access denied and an unknown database fail at once."
                    + " Default: ${DEFAULT-VALUE} s.")
    int waitS;

    /**
     * Options built in code (for {@code run}, whose --db is optional).
     *
     * @param url      the JDBC URL
     * @param user     the user, or null
     * @param password the password, or null
     * @param waitS    how long to wait, seconds
     * @return the options
     */
    public static DbOptions of(String url, String user, String password, int waitS) {
        DbOptions options = new DbOptions();
        options.url = url;
        options.user = user;
        options.password = password;
        options.waitS = waitS;
        return options;
    }

    /** @return the same options for the URL's server without its database (MariaDB, MySQL), or null for another URL */
    public DbOptions server() {
        Matcher m = SERVER_URL.matcher(url);
        if (!m.matches()) {
            return null;
        }
        return of(m.group(1) + "/" + (m.group(3) == null ? "" : m.group(3)), user, password, waitS);
    }

    /**
     * @param url a JDBC URL
     * @return the database a jdbc:mariadb:// or jdbc:mysql:// URL names, or null when it names none or is another kind
     */
    public static String databaseIn(String url) {
        Matcher m = url == null ? null : SERVER_URL.matcher(url);
        return m == null || !m.matches() || m.group(2) == null || m.group(2).isEmpty() ? null : m.group(2);
    }

    /**
     * Opens one connection, outside any pool (for the wait and for one-off statements).
     *
     * @return a connection; close it
     * @throws SQLException as the driver reports it
     */
    public Connection connect() throws SQLException {
        Properties props = new Properties();
        if (user != null) {
            props.setProperty("user", user);
        }
        if (password != null) {
            props.setProperty("password", password);
        }
        if (url.startsWith("jdbc:mariadb:") || url.startsWith("jdbc:mysql:")) {
            props.setProperty("connectTimeout", "5000"); // ms, both drivers: an unreachable host must not hang an attempt
        }
        return DriverManager.getConnection(Databases.withDialect(url), props);
    }

    /** @return the JDBC URL */
    public String url() {
        return url;
    }

    /** @return the user, or null to take it from the URL */
    public String user() {
        return user;
    }

    /** @return the password, or null */
    public String password() {
        return password;
    }

    /** @return how long to wait for the database, seconds */
    public int waitS() {
        return waitS;
    }

    /** @return why these options are unusable, or null when they are fine */
    public String problem() {
        if (!driverAccepts(url)) {
            return "--db must be a JDBC URL this program has a driver for (jdbc:mysql://..., jdbc:mariadb://...,"
                    + " jdbc:h2:...): " + redacted(url);
        }
        if (waitS < 0) {
            return "--wait-s must be >= 0: " + waitS;
        }
        return null;
    }

    /** @return whether a JDBC driver on the class path accepts the URL (checked before anything is written) */
    public static boolean driverAccepts(String url) {
        try {
            return url != null && url.startsWith("jdbc:") && DriverManager.getDriver(url) != null;
        } catch (SQLException e) {
            return false;
        }
    }

    /** @return the URL with any password in it replaced by {@code ***}: what may be printed on a console or a log */
    public static String redacted(String url) {
        return url == null ? null : PASSWORD_IN_URL.matcher(url).replaceAll("$1***");
    }
}
