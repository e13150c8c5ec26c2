package org.proactiverobotics.app.deploy;

import picocli.CommandLine.Option;

/**
 * The database options the two-process commands share (a picocli mixin). The password may come
 * from the environment, so that it never shows in a process list.
 */
public final class DbOptions {

    /** The environment variable a password defaults to. */
    public static final String PASSWORD_VARIABLE = "PROACTIVE_DB_PASSWORD";

    @Option(names = "--db", paramLabel = "JDBC_URL", required = true,
            description = "The shared database, e.g. jdbc:mysql://mysql:3306/proactive or jdbc:mariadb://127.0.0.1:3306/proactive.")
    String url;

    @Option(names = "--db-user", paramLabel = "U", description = "Database user (default: from the URL).")
    String user;

    @Option(names = "--db-password", paramLabel = "P", defaultValue = "${env:" + PASSWORD_VARIABLE + "}",
            description = "Database password. Default: the environment variable " + PASSWORD_VARIABLE + ".")
    String password;

    @Option(names = "--wait-s", paramLabel = "S", defaultValue = "60",
            description = "How long to wait for the database before giving up (exit 3). Default: ${DEFAULT-VALUE} s.")
    int waitS;

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
        if (!url.startsWith("jdbc:")) {
            return "--db must be a JDBC URL (jdbc:mysql://..., jdbc:mariadb://..., jdbc:h2:...): " + url;
        }
        if (waitS < 0) {
            return "--wait-s must be >= 0: " + waitS;
        }
        return null;
    }
}
