package org.proactiverobotics.db;

import com.zaxxer.hikari.HikariConfig;
import com.zaxxer.hikari.HikariDataSource;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Builds the connection pools both sides use: HikariCP over any JDBC URL (embedded H2 in MySQL
 * mode by default, MariaDB or MySQL 8 for deployment).
 */
public final class Databases {

    /**
     * H2 settings that make it accept schema.sql and the MySQL dialect both sides write; and a
     * per-session cache of 256 parsed statements rather than H2's 8: a control step runs about 25
     * distinct statements, more counting each row count of a {@link MultiRow} statement, so with 8
     * nearly every one was parsed again (engine iteration -35 %).
     */
    public static final String H2_MYSQL_MODE = ";MODE=MySQL;DATABASE_TO_LOWER=TRUE;DB_CLOSE_DELAY=-1;QUERY_CACHE_SIZE=256";

    /** The MariaDB driver's session variables in a URL: the key, then its comma-separated assignments. */
    private static final Pattern SESSION_VARIABLES = Pattern.compile("([?&]sessionVariables=)([^&]*)");

    private Databases() {
    }

    /**
     * An H2 URL with the settings of {@link #H2_MYSQL_MODE} it does not give itself appended (a
     * user's {@code jdbc:h2:/path/mission} then takes schema.sql instead of failing on its first
     * MySQL word); any other URL as it is.
     *
     * @param jdbcUrl a JDBC URL
     * @return the URL to connect with
     */
    public static String withDialect(String jdbcUrl) {
        if (!jdbcUrl.startsWith("jdbc:h2:")) {
            return jdbcUrl;
        }
        String upper = jdbcUrl.toUpperCase(Locale.ROOT);
        StringBuilder url = new StringBuilder(jdbcUrl);
        for (String setting : H2_MYSQL_MODE.substring(1).split(";")) {
            String key = setting.substring(0, setting.indexOf('=') + 1).toUpperCase(Locale.ROOT);
            if (!upper.contains(";" + key)) {
                url.append(';').append(setting);
            }
        }
        return url.toString();
    }

    /**
     * The URL of a named in-memory H2 database in MySQL mode; it lives as long as the JVM
     * (or until dropped), so several pools in one process share it.
     *
     * @param name letters, digits and underscores
     * @return a JDBC URL
     */
    public static String embeddedH2Url(String name) {
        if (!name.matches("[A-Za-z0-9_]+")) {
            throw new IllegalArgumentException("H2 database name must be letters, digits or '_': " + name);
        }
        return "jdbc:h2:mem:" + name + H2_MYSQL_MODE;
    }

    /**
     * A pool with this project's defaults: small (the workload is one writer per side), fast to
     * fail when the server is gone (3 s; 30 s for an in-process H2, which has no server to lose and
     * is only slow on a starved machine), and named after its user for the logs.
     *
     * @param jdbcUrl  a JDBC URL (jdbc:h2:..., jdbc:mariadb://..., jdbc:mysql://...)
     * @param user     the user, or null to take it from the URL
     * @param password the password, or null
     * @return a started pool; close it when done
     */
    public static HikariDataSource pool(String jdbcUrl, String user, String password) {
        return new HikariDataSource(config(jdbcUrl, user, password));
    }

    /**
     * The configuration {@link #pool} uses, for callers that need to adjust it (a shorter
     * connection time-out on the robot side, for instance) before starting the pool.
     *
     * @param jdbcUrl  a JDBC URL
     * @param user     the user, or null
     * @param password the password, or null
     * @return a configuration not yet used by any pool
     */
    public static HikariConfig config(String jdbcUrl, String user, String password) {
        HikariConfig config = new HikariConfig();
        config.setJdbcUrl(withDialect(jdbcUrl));
        if (user != null) {
            config.setUsername(user);
        }
        if (password != null) {
            config.setPassword(password);
        }
        config.setMaximumPoolSize(4);
        config.setMinimumIdle(1);
        // In-process H2 cannot be down: a short time-out would only fail a cold start on a busy machine.
        config.setConnectionTimeout(jdbcUrl.startsWith("jdbc:h2:mem:") ? 30_000 : 3_000);
        config.setValidationTimeout(1_000);
        // Fail on first use rather than at construction, so callers can wait for a database.
        config.setInitializationFailTimeout(-1);
        // H2's level on every database: InnoDB's default (repeatable read) takes gap locks, and
        // engines saving their first state at the same moment deadlocked on them.
        config.setTransactionIsolation("TRANSACTION_READ_COMMITTED");
        config.setPoolName("proactive-" + (user == null ? "pool" : user));
        // a JDBC batch as one round trip (the engine's changed queue rows, map chunks, requests;
        // the robot's readings): the MariaDB driver bulk-sends only inserts unless asked, and
        // MySQL's rewrites nothing unless asked. A setting in the URL wins.
        if (jdbcUrl.startsWith("jdbc:mariadb:") && !jdbcUrl.contains("useBulkStmts")) {
            config.addDataSourceProperty("useBulkStmts", "true");
        }
        // With a list of servers (a Galera cluster), a server that failed once is skipped for this
        // long: the driver's 60 s default outlasts a cluster's few seconds of stall after a node dies.
        if (isServerList(jdbcUrl)) {
            if (!jdbcUrl.contains("deniedListTimeout")) {
                config.addDataSourceProperty("deniedListTimeout", "1000");
            }
            // a Galera node answers reads from what it has applied: wait for the cluster's newest,
            // so that a process that moved to another node still reads its own commits (set by the
            // driver on every connection, the ones it makes when it moves too)
            if (!jdbcUrl.contains("wsrep_sync_wait")) {
                config.setJdbcUrl(withSessionVariable(config.getJdbcUrl(), "wsrep_sync_wait=1"));
            }
        }
        if (jdbcUrl.startsWith("jdbc:mysql:") && !jdbcUrl.contains("rewriteBatchedStatements")) {
            config.addDataSourceProperty("rewriteBatchedStatements", "true");
        }
        return config;
    }

    /** The URL with a session variable the driver sets on every connection, added to the URL's own ones. */
    private static String withSessionVariable(String jdbcUrl, String assignment) {
        Matcher m = SESSION_VARIABLES.matcher(jdbcUrl);
        if (m.find()) {
            String own = m.group(2);
            return jdbcUrl.substring(0, m.end(2)) + (own.isEmpty() ? "" : ",") + assignment + jdbcUrl.substring(m.end(2));
        }
        return jdbcUrl + (jdbcUrl.contains("?") ? "&" : "?") + "sessionVariables=" + assignment;
    }

    /**
     * @param jdbcUrl a JDBC URL
     * @return whether it names a list of MariaDB servers for the driver to fail over between
     *         ({@code jdbc:mariadb:sequential://a,b,c/db} or {@code loadbalance}), as for a Galera cluster
     */
    public static boolean isServerList(String jdbcUrl) {
        return jdbcUrl.startsWith("jdbc:mariadb:sequential:") || jdbcUrl.startsWith("jdbc:mariadb:loadbalance:");
    }

    /**
     * A pool as {@link #pool} makes, whose connections also take multi-statements: for an
     * engine, whose iteration's writes then go with its commit as one round trip.
     *
     * @param jdbcUrl  a JDBC URL
     * @param user     the user, or null
     * @param password the password, or null
     * @return a started pool; close it when done
     */
    public static HikariDataSource multiStatementPool(String jdbcUrl, String user, String password) {
        return new HikariDataSource(allowMultiStatements(config(jdbcUrl, user, password), jdbcUrl));
    }

    /**
     * Lets a pool's connections take a transaction as one multi-statement round trip
     * ({@link RoundTrip}) on MariaDB and MySQL; a setting in the URL wins. Only for the pools that
     * need it: stacked statements widen what an injected value could do (all our SQL binds values
     * through '?').
     *
     * @param config  a configuration from {@link #config}
     * @param jdbcUrl its URL
     * @return the configuration
     */
    public static HikariConfig allowMultiStatements(HikariConfig config, String jdbcUrl) {
        if ((jdbcUrl.startsWith("jdbc:mariadb:") || jdbcUrl.startsWith("jdbc:mysql:")) && !jdbcUrl.contains("allowMultiQueries")) {
            config.addDataSourceProperty("allowMultiQueries", "true");
        }
        return config;
    }
}
