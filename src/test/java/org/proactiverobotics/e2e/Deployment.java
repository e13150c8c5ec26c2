package org.proactiverobotics.e2e;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.proactiverobotics.app.Main;
import org.proactiverobotics.db.TestDatabases;
import org.yaml.snakeyaml.Yaml;

/**
 * The docker compose deployment without Docker, for the tests: the project's docker-compose.yml
 * as data; a fresh MariaDB database initialised by the very scripts the MySQL container runs
 * (schema.sql through the mysql client, then deploy/mysql-init/02-users.sh sourced with a
 * {@code docker_process_sql} of our own), with users of its own; and the compose services'
 * commands started as OS processes against it ({@link StartedProcesses}: ended, each with its
 * tree, at {@link #close()} and in any case when the test is over).
 */
final class Deployment implements AutoCloseable {

    /** The password both test users get (the users are unique per database, dropped at the end). */
    static final String ENGINE_PASSWORD = "engine-Pw&1";
    static final String ROBOT_PASSWORD = "robot-Pw&2";
    static final String VIEWER_PASSWORD = "viewer-Pw&3";

    private static final Pattern URL = Pattern.compile("jdbc:(?:mariadb|mysql)://([^:/?]+)(?::(\\d+))?/([^?]*)(\\?.*)?");

    private final String adminUrl;
    private final String host;
    private final String port;
    private final String adminUser;
    private final String adminPassword;
    final String database;
    final String engineUser;
    final String robotUser;
    final String viewerUser;
    private final List<Process> processes = new ArrayList<>();

    private Deployment(String adminUrl) {
        this.adminUrl = adminUrl;
        Matcher m = URL.matcher(adminUrl);
        if (!m.matches()) {
            throw new IllegalArgumentException("not a MariaDB URL: " + adminUrl);
        }
        this.host = m.group(1);
        this.port = m.group(2) == null ? "3306" : m.group(2);
        Map<String, String> query = query(m.group(4));
        this.adminUser = query.getOrDefault("user", "root");
        this.adminPassword = query.getOrDefault("password", "");
        String unique = UUID.randomUUID().toString().replace("-", "").substring(0, 10);
        this.database = "proactive_dep_" + unique;
        this.engineUser = "pe_" + unique;
        this.robotUser = "pr_" + unique;
        this.viewerUser = "pv_" + unique;
    }

    /** A fresh database with the compose init scripts applied; skips the test without MariaDB or a mysql client. */
    static Deployment create() throws Exception {
        String url = TestDatabases.mariaDbUrl();
        Assumptions.assumeTrue(url != null, "two-process tests skipped: set " + TestDatabases.MARIADB_URL_VARIABLE
                + " (e.g. jdbc:mariadb://127.0.0.1:3306/proactive_test?user=root&password=) to run them");
        Assumptions.assumeTrue(client() != null, "two-process tests skipped: no mysql or mariadb client on the PATH");
        Deployment d = new Deployment(url);
        try (Connection c = DriverManager.getConnection(url); Statement s = c.createStatement()) {
            s.execute("CREATE DATABASE " + d.database);
        }
        try {
            d.applyInitScripts();
        } catch (Exception e) {
            d.close();
            throw e;
        }
        return d;
    }

    /** As the MySQL entrypoint does: *.sql piped to the client on MYSQL_DATABASE, *.sh sourced with docker_process_sql. */
    private void applyInitScripts() throws Exception {
        for (String volume : Compose.load().mysqlInitVolumes()) {
            String[] parts = volume.split(":");
            Path script = root().resolve(parts[0]);
            String inContainer = parts[1];
            if (inContainer.endsWith(".sql")) {
                run(List.of(client(), "-h", host, "-P", port, "-u", adminUser, "--password=" + adminPassword,
                        "--database=" + database), script, Map.of());
            } else if (inContainer.endsWith(".sh")) {
                String shim = "docker_process_sql() { " + client() + " -h " + host + " -P " + port + " -u " + adminUser
                        + " --password=\"$ADMIN_PASSWORD\" --database=\"$MYSQL_DATABASE\" \"$@\"; }; set -eo pipefail; . \"$1\"";
                Map<String, String> env = new LinkedHashMap<>();
                env.put("ADMIN_PASSWORD", adminPassword);
                env.put("MYSQL_DATABASE", database);
                env.put("ENGINE_DB_PASSWORD", ENGINE_PASSWORD);
                env.put("ROBOT_DB_PASSWORD", ROBOT_PASSWORD);
                env.put("ENGINE_DB_USER", engineUser);
                env.put("ROBOT_DB_USER", robotUser);
                env.put("VIEWER_DB_PASSWORD", VIEWER_PASSWORD);
                env.put("VIEWER_DB_USER", viewerUser);
                env.put("PROACTIVE_USERS_SQL", root().resolve("deploy/users.sql").toString());
                run(List.of("bash", "-c", shim, "init", script.toString()), null, env);
            }
        }
    }

    private static void run(List<String> command, Path stdin, Map<String, String> env) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().putAll(env);
        if (stdin != null) {
            pb.redirectInput(stdin.toFile());
        }
        Process p = StartedProcesses.start(pb);
        try {
            String output = new String(p.getInputStream().readAllBytes());
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                throw new IllegalStateException(String.join(" ", command) + " failed: " + output);
            }
        } finally {
            StartedProcesses.end(p);
        }
    }

    /** @return a JDBC URL of this database with the driver compose uses (jdbc:mysql) */
    String url() {
        return "jdbc:mysql://" + host + ":" + port + "/" + database;
    }

    /** @return the admin URL of this database (MariaDB driver, user in the URL) */
    String adminUrl() {
        Matcher m = URL.matcher(adminUrl);
        m.matches();
        return "jdbc:mariadb://" + host + ":" + port + "/" + database + (m.group(4) == null ? "" : m.group(4));
    }

    /**
     * Starts a compose service's command as an OS process: the jar's {@code java -jar} becomes the
     * test class path, the compose values (MySQL host and database, users) become this
     * deployment's, and each of {@code options} replaces the value of that option in the compose
     * command (or is added when the command has none; a null value removes the option the command has).
     */
    Process start(String service, Map<String, String> options, Path log) throws IOException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        // a process logs as the jar does (its logback.xml), not as the test JVM (logback-test.xml quiets the robot)
        command.add("-Dlogback.configurationFile=logback.xml");
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(Main.class.getName());
        List<String> args = new ArrayList<>(Compose.load().service(service).command());
        if (!args.subList(0, 3).equals(List.of("java", "-jar", "/app/proactive.jar"))) {
            throw new IllegalStateException(service + " does not run the jar: " + args);
        }
        args = new ArrayList<>(args.subList(3, args.size()));
        for (int i = 0; i < args.size(); i++) {
            args.set(i, args.get(i).replace("jdbc:mysql://mysql:3306/proactive", url())
                    .replace("proactive_engine", engineUser).replace("proactive_robot", robotUser)
                    .replace("proactive_viewer", viewerUser)
                    .replace("/app/worlds/", root().resolve("worlds") + "/"));
        }
        for (Map.Entry<String, String> o : options.entrySet()) {
            int at = args.indexOf(o.getKey());
            if (at < 0) {
                args.add(o.getKey());
                if (o.getValue() != null) {
                    args.add(o.getValue());
                }
            } else if (o.getValue() != null) {
                args.set(at + 1, o.getValue());
            } else { // null for an option the command has: drop it and its value
                args.remove(at + 1);
                args.remove(at);
            }
        }
        command.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile());
        pb.environment().put("PROACTIVE_DB_PASSWORD", service.equals("engine") ? ENGINE_PASSWORD
                : service.equals("watch") ? VIEWER_PASSWORD : ROBOT_PASSWORD);
        pb.environment().remove("PROACTIVE_LOG_LEVEL");
        Process p = StartedProcesses.start(pb);
        processes.add(p);
        return p;
    }

    /** Waits until a log file holds a text; fails after the time-out. */
    static void awaitLog(Path log, String text, long timeoutS) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutS);
        while (System.nanoTime() < deadline) {
            if (Files.exists(log) && Files.readString(log).contains(text)) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("'" + text + "' not in " + log + " within " + timeoutS + " s:\n"
                + (Files.exists(log) ? Files.readString(log) : "(no log)"));
    }

    /** Runs one statement as the given user of this database. */
    void executeAs(String user, String password, String sql) throws SQLException {
        try (Connection c = DriverManager.getConnection("jdbc:mariadb://" + host + ":" + port + "/" + database, user, password);
             Statement s = c.createStatement()) {
            s.execute(sql);
        }
    }

    /** Runs one statement as the administrator. */
    void executeAsAdmin(String sql) throws SQLException {
        try (Connection c = DriverManager.getConnection(adminUrl()); Statement s = c.createStatement()) {
            s.execute(sql);
        }
    }

    /** @return the first column of the first row, as the administrator */
    long queryLong(String sql) throws SQLException {
        try (Connection c = DriverManager.getConnection(adminUrl()); Statement s = c.createStatement();
             var rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    @Override
    public void close() throws Exception {
        // before the database goes: a process left running would write into a dropped database
        StartedProcesses.end(processes);
        try (Connection c = DriverManager.getConnection(adminUrl); Statement s = c.createStatement()) {
            s.execute("DROP DATABASE IF EXISTS " + database);
            s.execute("DROP USER IF EXISTS '" + engineUser + "'@'%', '" + robotUser + "'@'%', '" + viewerUser + "'@'%'");
        }
    }

    /** @return the project root (where docker-compose.yml is) */
    static Path root() {
        Path dir = Path.of("").toAbsolutePath();
        while (dir != null && !Files.exists(dir.resolve("docker-compose.yml"))) {
            dir = dir.getParent();
        }
        if (dir == null) {
            throw new IllegalStateException("docker-compose.yml not found above " + Path.of("").toAbsolutePath());
        }
        return dir;
    }

    /** @return the mysql or mariadb client on the PATH, or null */
    static String client() {
        for (String name : new String[] {"mysql", "mariadb"}) {
            for (String dir : System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)) {
                if (Files.isExecutable(Path.of(dir, name))) {
                    return Path.of(dir, name).toString();
                }
            }
        }
        return null;
    }

    private static Map<String, String> query(String q) {
        Map<String, String> out = new LinkedHashMap<>();
        if (q == null || q.length() < 2) {
            return out;
        }
        for (String pair : q.substring(1).split("&")) {
            int eq = pair.indexOf('=');
            out.put(eq < 0 ? pair : pair.substring(0, eq), eq < 0 ? "" : pair.substring(eq + 1));
        }
        return out;
    }

    /** docker-compose.yml as data (SnakeYAML), with compose's ${VAR:-default} resolved to the defaults. */
    static final class Compose {
        private final Map<String, Object> root;

        private Compose(Map<String, Object> root) {
            this.root = root;
        }

        static Compose load() throws IOException {
            try (InputStream in = Files.newInputStream(root().resolve("docker-compose.yml"))) {
                Map<String, Object> yaml = new Yaml().load(in);
                return new Compose(yaml);
            }
        }

        /** @return the file's top-level keys and their values */
        Map<String, Object> topLevel() {
            return root;
        }

        @SuppressWarnings("unchecked")
        Map<String, Object> services() {
            return (Map<String, Object>) root.get("services");
        }

        @SuppressWarnings("unchecked")
        Map<String, Object> volumes() {
            return (Map<String, Object>) root.get("volumes");
        }

        @SuppressWarnings("unchecked")
        Service service(String name) {
            Map<String, Object> s = (Map<String, Object>) services().get(name);
            if (s == null) {
                throw new AssertionError("docker-compose.yml has no service " + name);
            }
            return new Service(s);
        }

        /** @return the mysql service's volumes mounted into /docker-entrypoint-initdb.d, in run order */
        List<String> mysqlInitVolumes() {
            return service("mysql").volumes().stream().filter(v -> v.contains(":/docker-entrypoint-initdb.d/"))
                    .sorted((a, b) -> a.split(":")[1].compareTo(b.split(":")[1])).toList();
        }

        /** One service. */
        static final class Service {
            private final Map<String, Object> map;

            Service(Map<String, Object> map) {
                this.map = map;
            }

            Object get(String key) {
                return map.get(key);
            }

            String image() {
                return (String) map.get("image");
            }

            @SuppressWarnings("unchecked")
            List<String> command() {
                return rawCommand().stream().map(Compose::resolve).toList();
            }

            /** @return the command as written, ${VAR:-default} unresolved */
            @SuppressWarnings("unchecked")
            List<String> rawCommand() {
                return ((List<Object>) map.get("command")).stream().map(String::valueOf).toList();
            }

            @SuppressWarnings("unchecked")
            List<String> volumes() {
                return ((List<Object>) map.getOrDefault("volumes", List.of())).stream().map(o -> resolve(String.valueOf(o))).toList();
            }

            @SuppressWarnings("unchecked")
            Map<String, Object> healthcheck() {
                return (Map<String, Object>) map.get("healthcheck");
            }

            @SuppressWarnings("unchecked")
            Map<String, Object> environment() {
                return (Map<String, Object>) map.getOrDefault("environment", Map.of());
            }

            @SuppressWarnings("unchecked")
            Map<String, Object> dependsOn() {
                return (Map<String, Object>) map.getOrDefault("depends_on", Map.of());
            }
        }

        private static final Pattern DEFAULTED = Pattern.compile("\\$\\{([A-Z_]+):-([^}]*)}");

        static String resolve(String s) {
            return DEFAULTED.matcher(s).replaceAll(m -> Matcher.quoteReplacement(m.group(2)));
        }
    }
}
