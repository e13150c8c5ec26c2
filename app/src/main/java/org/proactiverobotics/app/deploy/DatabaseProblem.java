package org.proactiverobotics.app.deploy;

import java.net.ConnectException;
import java.net.NoRouteToHostException;
import java.net.SocketTimeoutException;
import java.net.UnknownHostException;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Why a database cannot be used, for every command alike: the cause, classified from the JDBC
 * driver's exception (HikariCP's "Connection is not available" wrapper is looked through to the
 * driver's own cause), the driver's words, and what the user should do about it.
 */
public final class DatabaseProblem {

    /** What went wrong, and whether waiting can cure it. */
    public enum Cause {
        /** Nothing listens there (yet): a server still starting refuses connections. */
        UNREACHABLE(true),
        /** The host name does not resolve: in docker compose a service's name resolves only once it runs. */
        UNKNOWN_HOST(true),
        /** A table is missing: another process (db init, MySQL's init scripts) may still be applying the schema. */
        NO_SCHEMA(true),
        /** Wrong user or password, or no grant: the server says so at once and will say it again. */
        ACCESS_DENIED(false),
        /** The server runs but has no such database: nobody creates it while we wait. */
        UNKNOWN_DATABASE(false),
        /** The folder of an embedded H2 database's files cannot be created or written: nobody fixes it while we wait. */
        NO_FOLDER(false),
        /** No driver of ours accepts the URL. */
        UNSUPPORTED_URL(false),
        /** Anything else the driver reported: retried, since it may be a server in the middle of starting. */
        OTHER(true);

        private final boolean worthWaiting;

        Cause(boolean worthWaiting) {
            this.worthWaiting = worthWaiting;
        }

        /** @return whether retrying until --wait-s runs out can help */
        public boolean worthWaiting() {
            return worthWaiting;
        }
    }

    private static final Pattern AUTHORITY = Pattern.compile("jdbc:[a-z0-9]+:(?:[a-z:]+:)?//([^/?;]+)");
    private static final Pattern DATABASE_IN_MESSAGE = Pattern.compile("[Uu]nknown database '([^']*)'");
    private static final Pattern CONNECTION_ID = Pattern.compile("^\\(conn=\\d+\\)\\s*");

    private final Cause cause;
    private final String message;

    private DatabaseProblem(Cause cause, String message) {
        this.cause = cause;
        this.message = message;
    }

    /**
     * @param failure what the driver (or the pool around it) threw
     * @param url     the JDBC URL it was connecting to
     * @param table   the table that was read, or null
     * @return the classified problem
     */
    public static DatabaseProblem of(Throwable failure, String url, String table) {
        List<Throwable> chain = chain(failure);
        String words = driverWords(chain);
        String host = authority(url);
        if (find(chain, UnknownHostException.class) != null) {
            return new DatabaseProblem(Cause.UNKNOWN_HOST, "unknown database host " + hostName(host) + ": " + words
                    + " — check the host name in --db");
        }
        if (find(chain, ConnectException.class) != null || find(chain, NoRouteToHostException.class) != null
                || find(chain, SocketTimeoutException.class) != null) {
            return unreachable(host, words);
        }
        for (Throwable t : chain) {
            if (!(t instanceof SQLException e)) {
                continue;
            }
            String state = e.getSQLState() == null ? "" : e.getSQLState();
            int code = e.getErrorCode();
            String text = e.getMessage() == null ? "" : e.getMessage();
            if (state.equals("28000") || code == 1045 || code == 1698 || code == 1044 || text.contains("Access denied")) {
                return new DatabaseProblem(Cause.ACCESS_DENIED, "the database refused the user: " + words
                        + " — check the user and password (--db-user, --db-password or PROACTIVE_DB_PASSWORD,"
                        + " user= and password= in the URL) and the user's grants");
            }
            if (code == 1049 || code == 90146 || code == 90013 || DATABASE_IN_MESSAGE.matcher(text).find()) {
                String name = databaseName(text, url);
                return new DatabaseProblem(Cause.UNKNOWN_DATABASE, "no database '" + name + "' on the server: " + words
                        + " — create it (CREATE DATABASE " + name + ", or `db init --create`)");
            }
            if (state.startsWith("42S02") || code == 1146 || code == 42102 || code == 42104) {
                return new DatabaseProblem(Cause.NO_SCHEMA, "the schema is not applied"
                        + (table == null ? "" : " (table " + table + " missing)") + ": " + words
                        + " — apply it: `db init --db " + DbOptions.redacted(url) + "`");
            }
            if (text.startsWith("No suitable driver")) {
                return new DatabaseProblem(Cause.UNSUPPORTED_URL, words
                        + " — use jdbc:mariadb://..., jdbc:mysql://... or jdbc:h2:...");
            }
            if (state.startsWith("08")) {
                return unreachable(host, words);
            }
        }
        return new DatabaseProblem(Cause.OTHER, "database failure at " + (host == null ? DbOptions.redacted(url) : host) + ": " + words);
    }

    /**
     * @param message why the folder of an embedded H2 database's files cannot be used, and what to do
     * @return the problem, which waiting does not cure
     */
    static DatabaseProblem noFolder(String message) {
        return new DatabaseProblem(Cause.NO_FOLDER, message);
    }

    private static DatabaseProblem unreachable(String host, String words) {
        return new DatabaseProblem(Cause.UNREACHABLE, "cannot reach the database" + (host == null ? "" : " at " + host)
                + ": " + words + " — is the server running? start it, or check the host and port in --db");
    }

    /** @return the cause */
    public Cause cause() {
        return cause;
    }

    /** @return whether waiting can cure it */
    public boolean worthWaiting() {
        return cause.worthWaiting();
    }

    /** @return one line: what is wrong, in the driver's words, then what to do */
    public String message() {
        return message;
    }

    @Override
    public String toString() {
        return message;
    }

    private static List<Throwable> chain(Throwable failure) {
        List<Throwable> chain = new ArrayList<>();
        for (Throwable t = failure; t != null && !chain.contains(t); t = t.getCause()) {
            chain.add(t);
        }
        return chain;
    }

    private static Throwable find(List<Throwable> chain, Class<? extends Throwable> type) {
        return chain.stream().filter(type::isInstance).findFirst().orElse(null);
    }

    /**
     * The driver's own message: the innermost SQL exception's first line (not the pool's time-out
     * wrapper), then the network cause when it adds something ("Connection refused").
     */
    private static String driverWords(List<Throwable> chain) {
        String words = null;
        for (Throwable t : chain) {
            if (t instanceof SQLException && t.getMessage() != null && !isPoolTimeout(t)) {
                words = firstLine(t.getMessage());
                break;
            }
        }
        Throwable root = chain.get(chain.size() - 1);
        String rootWords = root.getMessage() == null ? root.getClass().getSimpleName() : firstLine(root.getMessage());
        if (words == null) {
            return rootWords;
        }
        return root instanceof SQLException || words.contains(rootWords) ? words : words + ": " + rootWords;
    }

    private static boolean isPoolTimeout(Throwable t) {
        return t.getClass().getName().equals("java.sql.SQLTransientConnectionException")
                && t.getMessage().contains("Connection is not available") && t.getCause() != null;
    }

    private static String firstLine(String s) {
        int nl = s.indexOf('\n');
        return CONNECTION_ID.matcher((nl < 0 ? s : s.substring(0, nl)).strip()).replaceFirst("");
    }

    private static String authority(String url) {
        Matcher m = url == null ? null : AUTHORITY.matcher(url);
        return m != null && m.lookingAt() ? m.group(1) : null;
    }

    private static String hostName(String authority) {
        if (authority == null) {
            return "(none in the URL)";
        }
        int at = authority.lastIndexOf('@');
        String hostPort = authority.substring(at + 1);
        int colon = hostPort.lastIndexOf(':');
        return colon > 0 && !hostPort.endsWith("]") ? hostPort.substring(0, colon) : hostPort;
    }

    private static String databaseName(String message, String url) {
        Matcher m = DATABASE_IN_MESSAGE.matcher(message);
        if (m.find()) {
            return m.group(1);
        }
        String name = DbOptions.databaseIn(url);
        return name == null ? DbOptions.redacted(url) : name;
    }
}
