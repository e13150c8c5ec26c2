package org.proactiverobotics.app.deploy;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.regex.Pattern;
import org.proactiverobotics.db.Schema;

/**
 * The least-privilege users script, deploy/users.sql (packaged in the jar), filled in: the same
 * template docker compose's MySQL initialisation applies through deploy/mysql-init/02-users.sh.
 */
public final class UsersScript {

    /** The default engine user. */
    public static final String ENGINE_USER = "proactive_engine";
    /** The default robot user. */
    public static final String ROBOT_USER = "proactive_robot";
    /** The default viewer user ({@code watch}: SELECT only). */
    public static final String VIEWER_USER = "proactive_viewer";

    private static final String RESOURCE = "users.sql";
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_]{1,32}");
    private static final Pattern HOST = Pattern.compile("[A-Za-z0-9_.%-]{1,255}");

    /**
     * The values of the template's placeholders.
     *
     * @param database       the database (schema) the users may use
     * @param host           the host pattern of both users ('%' = anywhere)
     * @param engineUser     the engine's user name
     * @param enginePassword its password
     * @param robotUser      the robot's user name
     * @param robotPassword  its password
     * @param viewerUser     the viewer's user name ({@code watch})
     * @param viewerPassword its password; null or empty: no viewer user
     */
    public record Values(String database, String host, String engineUser, String enginePassword, String robotUser,
                         String robotPassword, String viewerUser, String viewerPassword) {

        /** The engine and robot users only. */
        public Values(String database, String host, String engineUser, String enginePassword, String robotUser,
                      String robotPassword) {
            this(database, host, engineUser, enginePassword, robotUser, robotPassword, VIEWER_USER, null);
        }

        /** @return whether the viewer user is created too */
        public boolean withViewer() {
            return viewerPassword != null && !viewerPassword.isEmpty();
        }

        /** @return why these values cannot go into the script, or null when they can */
        public String problem() {
            for (String name : new String[] {database, engineUser, robotUser}) {
                if (name == null || !NAME.matcher(name).matches()) {
                    return "database and user names are 1 to 32 letters, digits or '_': " + name;
                }
            }
            if (engineUser.equals(robotUser)) {
                return "the engine and the robot need two different users: " + engineUser;
            }
            if (withViewer()) {
                if (viewerUser == null || !NAME.matcher(viewerUser).matches()) {
                    return "database and user names are 1 to 32 letters, digits or '_': " + viewerUser;
                }
                if (viewerUser.equals(engineUser) || viewerUser.equals(robotUser)) {
                    return "the viewer needs a user of its own: " + viewerUser;
                }
                if (viewerPassword.indexOf('\'') >= 0 || viewerPassword.indexOf('\\') >= 0
                        || viewerPassword.chars().anyMatch(ch -> ch < 0x20)) {
                    return "a password must not contain ', \\ or control characters";
                }
            }
            if (host == null || !HOST.matcher(host).matches()) {
                return "the host pattern is letters, digits, '.', '-', '_' or '%': " + host;
            }
            for (String password : new String[] {enginePassword, robotPassword}) {
                if (password == null || password.isEmpty()) {
                    return "both passwords are needed (--engine-password / ENGINE_DB_PASSWORD, --robot-password / ROBOT_DB_PASSWORD)";
                }
                if (password.indexOf('\'') >= 0 || password.indexOf('\\') >= 0 || password.chars().anyMatch(ch -> ch < 0x20)) {
                    return "a password must not contain ', \\ or control characters";
                }
            }
            return null;
        }
    }

    private UsersScript() {
    }

    /** @return the template as packaged */
    public static String template() {
        try (InputStream in = UsersScript.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("users.sql is missing from the app jar");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * The script filled in, under a header of its own: the template's header explains the placeholders, and a
     * filled copy of it would repeat the passwords. Passwords go only into the statements that set them, never
     * into a comment.
     *
     * @param values the placeholders' values (checked: see {@link Values#problem()})
     * @return the script, filled in
     */
    public static String filled(Values values) {
        String problem = values.problem();
        if (problem != null) {
            throw new IllegalArgumentException(problem);
        }
        StringBuilder script = new StringBuilder()
                .append("-- proactive-robotics: the least-privilege users ").append(values.engineUser()).append(" and ")
                .append(values.robotUser()).append(" (host '").append(values.host()).append("') on database `")
                .append(values.database()).append("`,\n")
                .append("-- deploy/users.sql filled in by `proactive db users`. Apply it as an administrator after schema.sql.\n")
                .append("-- Idempotent: applying it again resets the passwords and adds no privilege.\n\n");
        List<String> lines = template().lines().toList();
        int body = 0;
        while (body < lines.size() && (lines.get(body).startsWith("--") || lines.get(body).isBlank())) {
            body++; // the template's header
        }
        for (String line : lines.subList(body, lines.size())) {
            if (!values.withViewer() && line.contains("@VIEWER_")) {
                continue;
            }
            String filled = line.replace("@DATABASE@", values.database()).replace("@HOST@", values.host())
                    .replace("@ENGINE_USER@", values.engineUser()).replace("@ROBOT_USER@", values.robotUser())
                    .replace("@VIEWER_USER@", values.viewerUser());
            if (!line.startsWith("--")) {
                filled = filled.replace("@ENGINE_PASSWORD@", values.enginePassword())
                        .replace("@ROBOT_PASSWORD@", values.robotPassword());
                if (values.withViewer()) {
                    filled = filled.replace("@VIEWER_PASSWORD@", values.viewerPassword());
                }
            }
            script.append(filled).append('\n');
        }
        return script.toString();
    }

    /**
     * @param script a filled script
     * @return its statements, "--" comment lines dropped (a statement ends with ';' at a line end)
     */
    public static List<String> statements(String script) {
        return Schema.split(script);
    }
}
