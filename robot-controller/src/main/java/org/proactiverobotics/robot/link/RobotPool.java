package org.proactiverobotics.robot.link;

import com.zaxxer.hikari.HikariConfig;
import com.zaxxer.hikari.HikariDataSource;
import java.sql.DriverManager;
import org.proactiverobotics.db.Databases;

/**
 * The robot's connection pool: the project's defaults ({@link Databases#config}) with a short
 * connection time-out, so that a database that is gone costs the control loop a fraction of a
 * second per retry, not the usual 30 s; on MariaDB / MySQL also a socket time-out
 * ({@value #SOCKET_TIMEOUT_MS} ms), so that a server that hangs mid-statement cannot freeze it. The
 * driver's own time to open a connection ({@value #DRIVER_CONNECT_TIMEOUT_MS} ms) is longer than the
 * pool's wait: the pool opens connections on a thread of its own, so a server slow to greet a new
 * connection (a starved machine) still ends up giving one, while the control loop waits no longer.
 */
public final class RobotPool {

    /** The default time to wait for a connection, milliseconds. */
    public static final long DEFAULT_CONNECTION_TIMEOUT_MS = 500;

    /** The longest wait for a MariaDB / MySQL server's answer to one statement, milliseconds. */
    public static final int SOCKET_TIMEOUT_MS = 2_000;

    /**
     * The longest a MariaDB / MySQL driver may take to open one connection (TCP connect and the
     * server's greeting), milliseconds: as long as the start-up's wait gives one attempt
     * ({@code DbOptions.connect}), so that a busy server is not taken for a gone one.
     */
    public static final int DRIVER_CONNECT_TIMEOUT_MS = 5_000;

    private RobotPool() {
    }

    /**
     * @param jdbcUrl             a JDBC URL
     * @param user                the user, or null to take it from the URL
     * @param password            the password, or null
     * @param connectionTimeoutMs the longest wait for a connection, ms (at least 250, Hikari's minimum)
     * @return a started pool (it does not fail when the database is not there yet); close it when done
     */
    public static HikariDataSource open(String jdbcUrl, String user, String password, long connectionTimeoutMs) {
        // the robot's answers go as one round trip each (JdbcRobotLink)
        HikariConfig config = Databases.allowMultiStatements(Databases.config(jdbcUrl, user, password), jdbcUrl);
        config.setConnectionTimeout(Math.max(250, connectionTimeoutMs));
        config.setValidationTimeout(250);
        config.setMaximumPoolSize(3); // the link, a read beside it, and the handshake's locks (HandshakeLocks)
        config.setMinimumIdle(3); // all opened at start: on a busy server a connection opened mid-mission can come too late for a step
        config.setPoolName("proactive-robot");
        if (jdbcUrl.startsWith("jdbc:mariadb:") || jdbcUrl.startsWith("jdbc:mysql:")) {
            // A server that stops answering must not freeze the control loop (both drivers: ms).
            config.addDataSourceProperty("socketTimeout", String.valueOf(SOCKET_TIMEOUT_MS));
            config.addDataSourceProperty("connectTimeout", String.valueOf(DRIVER_CONNECT_TIMEOUT_MS));
        }
        int loginTimeoutS = DriverManager.getLoginTimeout();
        HikariDataSource pool = new HikariDataSource(config);
        // HikariCP sets the JVM-wide login time-out from the pool's short wait (1 s), and the MySQL driver bounds a
        // server's greeting with it: a busy server would never give this pool, nor the start-up's wait, a connection
        DriverManager.setLoginTimeout(loginTimeoutS);
        return pool;
    }

    /** {@link #open(String, String, String, long)} with {@value #DEFAULT_CONNECTION_TIMEOUT_MS} ms. */
    public static HikariDataSource open(String jdbcUrl, String user, String password) {
        return open(jdbcUrl, user, password, DEFAULT_CONNECTION_TIMEOUT_MS);
    }
}
