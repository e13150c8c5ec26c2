package org.proactiverobotics.app;

import java.io.PrintWriter;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.concurrent.Callable;
import java.util.regex.Pattern;
import org.proactiverobotics.app.deploy.DatabaseProblem;
import org.proactiverobotics.app.deploy.DatabaseWait;
import org.proactiverobotics.app.deploy.DbOptions;
import org.proactiverobotics.app.deploy.UsersScript;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.Schema;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code db}: prepares an existing MySQL 8 / MariaDB server for the two processes, as an
 * administrator: {@code init} applies schema.sql, {@code users} creates the engine's and the
 * robot's least-privilege users (deploy/users.sql, the script docker compose applies). Both
 * are idempotent.
 */
@Command(name = "db",
        mixinStandardHelpOptions = true,
        description = {"Prepares a database for the engine and robot processes (as an administrator).",
                "Exit codes: 0 done, 2 bad input, 3 database failure."},
        subcommands = {DbCommand.Init.class, DbCommand.Users.class})
public final class DbCommand implements Runnable {

    @Spec
    private CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "Missing subcommand: init or users");
    }

    /** {@code db init}: applies schema.sql. */
    @Command(name = "init", mixinStandardHelpOptions = true,
            description = {"Creates every table of schema.sql that does not exist yet (harmless to repeat).",
                    "The URL's database must exist, or --create makes it."})
    static final class Init implements Callable<Integer> {

        @Mixin
        private DbOptions db;

        @Option(names = "--create", description = "Create the URL's database first when it does not exist (MariaDB, MySQL:"
                + " CREATE DATABASE IF NOT EXISTS, as a user who may). An H2 embedded or file database is created on"
                + " first use anyway.")
        private boolean create;

        @Spec
        private CommandSpec spec;

        @Override
        public Integer call() {
            PrintWriter err = spec.commandLine().getErr();
            if (db.problem() != null) {
                return fail(err, db.problem(), Main.EXIT_BAD_INPUT);
            }
            PrintWriter out = spec.commandLine().getOut();
            if (create && db.server() != null && !DATABASE_NAME.matcher(String.valueOf(DbOptions.databaseIn(db.url()))).matches()) {
                return fail(err, "--create needs a database name of letters, digits, '_' or '$' in --db: " + DbOptions.redacted(db.url()),
                        Main.EXIT_BAD_INPUT);
            }
            try {
                awaitOrCreate(out);
                try (var pool = Databases.pool(db.url(), db.user(), db.password())) {
                    Schema.apply(pool);
                }
            } catch (DatabaseWait.Unreachable e) {
                return fail(err, e.getMessage(), Main.EXIT_INFRASTRUCTURE);
            } catch (SQLException e) {
                return fail(err, DatabaseProblem.of(e, db.url(), null).message(), Main.EXIT_INFRASTRUCTURE);
            }
            out.println("schema.sql applied: " + Schema.tableNames().size() + " tables");
            out.flush();
            return 0;
        }

        /** Waits for the database; with --create, makes it when the server says it does not exist. */
        private void awaitOrCreate(PrintWriter out) throws DatabaseWait.Unreachable, SQLException {
            try {
                DatabaseWait.await(db, null, () -> false);
                return;
            } catch (DatabaseWait.Unreachable e) {
                DbOptions server = db.server();
                if (!create || server == null || e.problem().cause() != DatabaseProblem.Cause.UNKNOWN_DATABASE) {
                    throw e;
                }
            }
            String name = DbOptions.databaseIn(db.url());
            try (Connection c = db.server().connect(); Statement s = c.createStatement()) {
                s.execute("CREATE DATABASE IF NOT EXISTS `" + name + "`");
            }
            out.println("database " + name + " created");
            DatabaseWait.await(db, null, () -> false);
        }
    }

    /** {@code db users}: creates the two least-privilege users. */
    @Command(name = "users", mixinStandardHelpOptions = true,
            description = {"Creates (or updates) the engine's and the robot's users with their grants on the URL's database.",
                    "Apply `db init` first. The engine user reads the robot's tables and writes its own; the robot user"
                            + " writes its readings, answers requests and reads commands; neither may create, drop, alter"
                            + " or grant."})
    static final class Users implements Callable<Integer> {

        @Mixin
        private DbOptions db;

        @Option(names = "--engine-user", paramLabel = "NAME", defaultValue = UsersScript.ENGINE_USER,
                description = "Default: ${DEFAULT-VALUE}.")
        private String engineUser;

        @Option(names = "--engine-password", paramLabel = "P", defaultValue = "${env:ENGINE_DB_PASSWORD}",
                description = "Default: the environment variable ENGINE_DB_PASSWORD.")
        private String enginePassword;

        @Option(names = "--robot-user", paramLabel = "NAME", defaultValue = UsersScript.ROBOT_USER,
                description = "Default: ${DEFAULT-VALUE}.")
        private String robotUser;

        @Option(names = "--robot-password", paramLabel = "P", defaultValue = "${env:ROBOT_DB_PASSWORD}",
                description = "Default: the environment variable ROBOT_DB_PASSWORD.")
        private String robotPassword;

        @Option(names = "--viewer-user", paramLabel = "NAME", defaultValue = UsersScript.VIEWER_USER,
                description = "The `watch` user (SELECT only). Default: ${DEFAULT-VALUE}.")
        private String viewerUser;

        @Option(names = "--viewer-password", paramLabel = "P", defaultValue = "${env:VIEWER_DB_PASSWORD}",
                description = "Creates the viewer user too. Default: the environment variable VIEWER_DB_PASSWORD (none: no viewer).")
        private String viewerPassword;

        @Option(names = "--host", paramLabel = "PATTERN", defaultValue = "%",
                description = "Where the users may connect from. Default: ${DEFAULT-VALUE} (anywhere).")
        private String host;

        @Option(names = "--print", description = "Print the script for the URL's database name instead of applying it (no connection).")
        private boolean print;

        @Spec
        private CommandSpec spec;

        @Override
        public Integer call() {
            PrintWriter err = spec.commandLine().getErr();
            PrintWriter out = spec.commandLine().getOut();
            if (db.problem() != null) {
                return fail(err, db.problem(), Main.EXIT_BAD_INPUT);
            }
            UsersScript.Values check = values(print ? databaseInUrl(db.url()) : "db");
            if (check.problem() != null) {
                return fail(err, check.problem(), Main.EXIT_BAD_INPUT);
            }
            if (print) {
                out.print(UsersScript.filled(check));
                out.flush();
                return 0;
            }
            try {
                DatabaseWait.await(db, null, () -> false);
            } catch (DatabaseWait.Unreachable e) {
                return fail(err, e.getMessage(), Main.EXIT_INFRASTRUCTURE);
            }
            try (var pool = Databases.pool(db.url(), db.user(), db.password()); Connection c = pool.getConnection();
                 Statement s = c.createStatement()) {
                String database;
                try (ResultSet rs = s.executeQuery("SELECT DATABASE()")) {
                    rs.next();
                    database = rs.getString(1);
                }
                if (database == null) {
                    return fail(err, "the URL names no database: " + DbOptions.redacted(db.url()), Main.EXIT_BAD_INPUT);
                }
                UsersScript.Values values = values(database);
                if (values.problem() != null) {
                    return fail(err, values.problem(), Main.EXIT_BAD_INPUT);
                }
                for (String sql : UsersScript.statements(UsersScript.filled(values))) {
                    s.execute(sql);
                }
                out.println("users " + engineUser + " and " + robotUser + (values.withViewer() ? " and " + viewerUser : "")
                        + " granted on " + database + " (host '" + host + "')");
                out.flush();
                return 0;
            } catch (SQLException e) {
                return fail(err, "creating the users failed: " + DatabaseProblem.of(e, db.url(), null).message(),
                        Main.EXIT_INFRASTRUCTURE);
            }
        }

        private UsersScript.Values values(String database) {
            return new UsersScript.Values(database, host, engineUser, enginePassword, robotUser, robotPassword, viewerUser,
                    viewerPassword);
        }

        /** The database name of a jdbc:mysql:// or jdbc:mariadb:// URL, for --print. */
        private static String databaseInUrl(String url) {
            int slash = url.indexOf('/', url.indexOf("//") + 2);
            if (url.indexOf("//") < 0 || slash < 0) {
                return null;
            }
            String rest = url.substring(slash + 1);
            int q = rest.indexOf('?');
            return q < 0 ? rest : rest.substring(0, q);
        }
    }

    /** A database name that needs no quoting beyond backticks (MariaDB and MySQL identifiers). */
    private static final Pattern DATABASE_NAME = Pattern.compile("[A-Za-z0-9_$]{1,64}");

    private static int fail(PrintWriter err, String message, int code) {
        err.println(message);
        err.flush();
        return code;
    }
}
