package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.Main;
import org.proactiverobotics.db.TestDatabases;

/**
 * The README's and the docs' commands as a user pastes them (issue 16): the {@code ```bash} blocks of
 * the sections below that call {@code app/target/proactive.jar} run in order, as one bash script, on
 * the MariaDB of PROACTIVE_TEST_MARIADB_URL; the test fails when one of them fails, and when a
 * section loses its commands (so the README cannot drift away from what works). What a test must
 * change, and only that: the jar is this build's class path in a child JVM (the jar is packaged
 * after the tests), every database gets a fresh name (dropped at the end), every server URL
 * becomes the test server's, output under /tmp goes to a temporary directory, {@code db users}
 * creates users of its own (dropped at the end), and {@code ./mvnw} (the build running this
 * test) is left out. The walk is long and runs with the long tests ({@code -Preliability}); the
 * check that the blocks are still there runs in the normal suite.
 */
class ReadmeCommandsTest {

    /** The sections whose database set-up blocks must be there and must work, in the order they run. */
    private static final List<Section> SECTIONS = List.of(new Section("README.md", "Two commands"),
            new Section("docs/deployment.md", "An existing server: schema and users"),
            new Section("docs/testing.md", "On MariaDB too"), new Section("docs/performance.md", "How to measure"));
    private static final String JAR = "java -jar app/target/proactive.jar";
    private static final Pattern README_URL = Pattern.compile("jdbc:mariadb://127\\.0\\.0\\.1:3306/(\\w+)\\?user=root&password=");
    private static final Pattern SERVER = Pattern.compile("(jdbc:(?:mariadb|mysql)://[^/?]+)/([^?]*)(\\?.*)?");
    private static final Pattern BLOCK = Pattern.compile("^```bash\\n(.*?)^```", Pattern.DOTALL | Pattern.MULTILINE);

    @TempDir
    Path tmp;

    @Test
    void everySectionStillHasItsCommands() throws IOException {
        Map<Section, List<String>> blocks = jarBlocks();
        for (Section section : SECTIONS) {
            assertThat(blocks.get(section)).as("%s has a ```bash block running %s", section, JAR)
                    .isNotNull().isNotEmpty();
        }
        String all = String.join("\n", blocks.values().stream().flatMap(List::stream).toList());
        assertThat(all).as("the database set-up commands").contains(JAR + " db init --create").contains(JAR + " db users")
                .contains(JAR + " run --quiet --out /tmp/ref-mariadb --db");
        assertThat(README_URL.matcher(all).results().count()).as("every MariaDB URL in the form this test substitutes")
                .isEqualTo(Pattern.compile("jdbc:mariadb:").matcher(all).results().count());
    }

    @Test
    @Tag("reliability") // long (three missions, one over MariaDB: about 30 s): with the long tests, -Preliability
    void theDatabaseBlocksWorkWhenPastedInOrderOnAFreshDatabase() throws Exception {
        String base = TestDatabases.mariaDbUrl();
        Assumptions.assumeTrue(base != null, "README commands not run: set " + TestDatabases.MARIADB_URL_VARIABLE
                + " (e.g. jdbc:mariadb://127.0.0.1:3306/proactive_test?user=root&password=) to run them");
        Matcher server = SERVER.matcher(base);
        assertThat(server.matches()).as(base).isTrue();
        String suffix = "_readme_" + UUID.randomUUID().toString().substring(0, 8);
        String engineUser = "pe" + suffix;
        String robotUser = "pr" + suffix;
        Set<String> databases = new LinkedHashSet<>();

        StringBuilder script = new StringBuilder("set -euo pipefail\n");
        for (List<String> blocks : jarBlocks().values()) {
            for (String block : blocks) {
                for (String line : block.split("\n")) {
                    script.append(asTestRuns(line, server, suffix, databases, engineUser, robotUser)).append('\n');
                }
            }
        }
        // a block that leaves a process running would write into the temporary directory after the test
        script.append("left=$(jobs -p); if [ -n \"$left\" ]; then echo \"a README block left processes running: $left\";"
                + " kill $left; wait; exit 1; fi\n");
        Path log = tmp.resolve("readme.log");
        ProcessBuilder pb = new ProcessBuilder("bash", "-x", "-c", script.toString()).directory(tmp.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile());
        pb.environment().put("PROACTIVE_JAVA", Path.of(System.getProperty("java.home"), "bin", "java").toString());
        pb.environment().put("PROACTIVE_CP", System.getProperty("java.class.path"));
        pb.environment().remove(TestDatabases.MARIADB_URL_VARIABLE); // the README sets it itself
        try {
            Process bash = StartedProcesses.start(pb);
            boolean ended = bash.waitFor(5, TimeUnit.MINUTES);
            // the script and what it left running (a failed block leaves its background jobs) end before the databases go
            StartedProcesses.end(bash);
            String output = Files.readString(log, StandardCharsets.UTF_8);
            assertThat(ended).as(output).isTrue();
            assertThat(bash.exitValue()).as("a README command failed (the last + line):\n" + output).isZero();
            assertThat(output).contains("schema.sql applied").contains("granted on")
                    .contains("MISSION_ACCOMPLISHED");
            assertThat(tmp.resolve("ref-mariadb/report.json")).isRegularFile();
            assertThat(databases).hasSizeGreaterThanOrEqualTo(2);
        } finally {
            dropAll(base, databases, engineUser, robotUser);
        }
    }

    /** One README line as the test runs it (see the class comment). */
    private String asTestRuns(String line, Matcher server, String suffix, Set<String> databases, String engineUser,
                              String robotUser) {
        String l = line.strip();
        if (l.startsWith("./mvnw")) {
            int and = l.indexOf("&&");
            if (and < 0) {
                return ": skipped " + l.replace("'", "");
            }
            l = l.substring(and + 2).strip();
        }
        l = l.replace(JAR, "\"$PROACTIVE_JAVA\" -cp \"$PROACTIVE_CP\" " + Main.class.getName());
        Matcher url = README_URL.matcher(l);
        StringBuilder out = new StringBuilder();
        while (url.find()) {
            String database = url.group(1) + suffix;
            databases.add(database);
            url.appendReplacement(out, Matcher.quoteReplacement(server.group(1) + "/" + database
                    + (server.group(3) == null ? "" : server.group(3))));
        }
        url.appendTail(out);
        l = out.toString().replace("--out /tmp/", "--out " + tmp + "/");
        if (l.contains(Main.class.getName() + " db users")) {
            l += " --engine-user " + engineUser + " --robot-user " + robotUser;
        }
        return l;
    }

    /** A {@code ## } section of a Markdown file of the repository. */
    private record Section(String file, String heading) {
        @Override
        public String toString() {
            return file + " section '" + heading + "'";
        }
    }

    /** The ```bash blocks of {@link #SECTIONS} that run the jar, by section, in that order. */
    private static Map<Section, List<String>> jarBlocks() throws IOException {
        Map<Section, List<String>> blocks = new LinkedHashMap<>();
        for (Section section : SECTIONS) {
            String text = Files.readString(Deployment.root().resolve(section.file()), StandardCharsets.UTF_8);
            Matcher m = BLOCK.matcher(text);
            while (m.find()) {
                if (section.heading().equals(sectionAt(text, m.start())) && m.group(1).contains(JAR)) {
                    blocks.computeIfAbsent(section, s -> new ArrayList<>()).add(m.group(1));
                }
            }
        }
        return blocks;
    }

    private static String sectionAt(String readme, int offset) {
        int heading = readme.lastIndexOf("\n## ", offset);
        if (heading < 0) {
            return "";
        }
        int end = readme.indexOf('\n', heading + 1);
        return readme.substring(heading + 4, end).strip();
    }

    private static void dropAll(String base, Set<String> databases, String engineUser, String robotUser) throws SQLException {
        try (Connection c = DriverManager.getConnection(base); Statement s = c.createStatement()) {
            for (String database : databases) {
                s.execute("DROP DATABASE IF EXISTS `" + database + "`");
            }
            s.execute("DROP USER IF EXISTS '" + engineUser + "'@'%', '" + robotUser + "'@'%'");
        }
    }
}
