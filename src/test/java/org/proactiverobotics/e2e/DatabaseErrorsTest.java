package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.proactiverobotics.app.Main;
import org.proactiverobotics.db.TestDatabases;

/**
 * One database-error path for every command (issue 16): a closed port, an unknown host, a wrong
 * password and a missing database each end run, engine, robot, strategy and db init with exit 3,
 * the cause in the driver's words and what to do, within --wait-s (at once for the causes waiting
 * cannot cure), and nothing written. The wrong password and the missing database need a server:
 * they run on the MariaDB of PROACTIVE_TEST_MARIADB_URL, skipped without it.
 */
class DatabaseErrorsTest extends CommandLineTest {

    private static final List<String> COMMANDS = List.of("run", "engine", "robot", "strategy", "db init");
    private static final Pattern SERVER = Pattern.compile("(jdbc:(?:mariadb|mysql)://[^/?]+)/([^?]*)(\\?.*)?");

    @TempDir
    Path tmp;

    /** A cause, how to provoke it, what the message must say. */
    private record Cause(String name, String url, boolean needsServer, boolean permanent, List<String> expected) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Arguments> commandsAndCauses() throws IOException {
        int closedPort;
        try (ServerSocket socket = new ServerSocket(0)) {
            closedPort = socket.getLocalPort(); // free now, and nobody listens once it is closed
        }
        String server = server();
        String missing = "proactive_missing_" + UUID.randomUUID().toString().substring(0, 8).replace("-", "");
        List<Cause> causes = List.of(
                new Cause("closed port", "jdbc:mariadb://127.0.0.1:" + closedPort + "/proactive?user=root", false, false,
                        List.of("cannot reach the database at 127.0.0.1:" + closedPort, "Connection refused",
                                "is the server running? start it, or check the host and port in --db")),
                new Cause("unknown host", "jdbc:mariadb://no-such-host.invalid:3306/proactive?user=root", false, false,
                        List.of("unknown database host no-such-host.invalid", "check the host name in --db")),
                new Cause("wrong password", server + "/mysql?user=proactive_no_such_user&password=wrong", true, true,
                        List.of("the database refused the user", "Access denied for user 'proactive_no_such_user'",
                                "check the user and password (--db-user, --db-password or PROACTIVE_DB_PASSWORD")),
                new Cause("missing database", server + "/" + missing + query(), true, true,
                        List.of("Unknown database '" + missing + "'",
                                "create it (CREATE DATABASE " + missing + ", or `db init --create`)")));
        List<Arguments> cases = new ArrayList<>();
        for (String command : COMMANDS) {
            for (Cause cause : causes) {
                cases.add(Arguments.of(command, cause));
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0}: {1}")
    @MethodSource("commandsAndCauses")
    void exitsThreeNamingTheCauseAndWhatToDoAndWritesNothing(String command, Cause cause) {
        Assumptions.assumeTrue(!cause.needsServer() || TestDatabases.mariaDbUrl() != null,
                "needs a MariaDB server: set " + TestDatabases.MARIADB_URL_VARIABLE + " to run it");
        Path outDir = tmp.resolve("out");
        // A server that is not up is worth --wait-s (0 here: one attempt); a permanent cause fails at once even with 30.
        String waitS = cause.permanent() ? "30" : "0";
        long start = System.nanoTime();
        int code = run(args(command, cause.url(), waitS, outDir));
        long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        String text = err.toString();
        assertThat(code).as(text).isEqualTo(3);
        for (String expected : cause.expected()) {
            assertThat(text).contains(expected);
        }
        assertThat(text).doesNotContain("Connection is not available").doesNotContain("\tat ");
        assertThat(tookMs).as("ms").isLessThan(8_000);
        assertThat(outDir).doesNotExist();
    }

    @Test
    void runWaitsForAServerThatIsNotUpForWaitSThenGivesUp() throws IOException {
        int closedPort;
        try (ServerSocket socket = new ServerSocket(0)) {
            closedPort = socket.getLocalPort();
        }
        Path outDir = tmp.resolve("out");
        long start = System.nanoTime();
        int code = run(args("run", "jdbc:mariadb://127.0.0.1:" + closedPort + "/proactive?user=root", "1", outDir));
        long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertThat(code).as(err.toString()).isEqualTo(3);
        assertThat(err.toString()).contains("database not usable within 1 s (--wait-s").contains("Connection refused");
        assertThat(tookMs).isBetween(1_000L, 8_000L);
        assertThat(outDir).doesNotExist();
        assertThat(out.toString()).isEmpty();
    }

    /**
     * H2 prints a stack trace of its own on the console when it cannot write its folder: the
     * process, not only the command's error stream, must show one line.
     */
    @Test
    void anH2FileDatabaseInAFolderThatCannotBeMadeIsOneLineOfTheProcessAndWritesNothing() throws Exception {
        Path file = Files.writeString(tmp.resolve("not-a-folder"), "keep me");
        Path outDir = tmp.resolve("out");
        Process p = StartedProcesses.start(new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Dlogback.configurationFile=logback.xml", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "run", "--db", "jdbc:h2:" + file.resolve("sub/mission"), "--wait-s", "2", "--quiet", "--out", outDir.toString())
                .redirectErrorStream(true));
        String printed = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(printed).isEqualTo(3);
        assertThat(printed.lines().toList()).as(printed).containsExactly("cannot create the H2 database's folder "
                + file.resolve("sub") + " (Not a directory): give --db a path in a folder you can write to");
        assertThat(outDir).doesNotExist();
        assertThat(Files.readString(file)).isEqualTo("keep me");
    }

    private static String[] args(String command, String url, String waitS, Path outDir) {
        List<String> args = new ArrayList<>(List.of(command.split(" ")));
        args.addAll(List.of("--db", url, "--wait-s", waitS));
        if (command.equals("run") || command.equals("robot")) {
            args.addAll(List.of("--out", outDir.toString()));
        }
        if (command.equals("run")) {
            args.add("--quiet");
        }
        if (command.equals("robot")) {
            args.addAll(List.of("--world", Deployment.root().resolve("worlds/reference-arena.json").toString()));
        }
        return args.toArray(String[]::new);
    }

    /** The MariaDB test server's address part, or a placeholder when none is configured (those cases are skipped). */
    private static String server() {
        Matcher m = TestDatabases.mariaDbUrl() == null ? null : SERVER.matcher(TestDatabases.mariaDbUrl());
        return m != null && m.matches() ? m.group(1) : "jdbc:mariadb://127.0.0.1:3306";
    }

    private static String query() {
        Matcher m = TestDatabases.mariaDbUrl() == null ? null : SERVER.matcher(TestDatabases.mariaDbUrl());
        return m != null && m.matches() && m.group(3) != null ? m.group(3) : "";
    }
}
