package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.Main;

/** The engine, robot, strategy and db commands' input checks and waits, without a database. */
class DeployCommandsTest extends CommandLineTest {

    @TempDir
    Path tmp;

    @Test
    void everyCommandHasHelp() {
        for (String command : List.of("engine", "robot", "strategy", "db")) {
            assertThat(run(command, "--help")).as(command).isZero();
        }
        assertThat(out.toString()).contains("--db=JDBC_URL").contains("--timing").contains("--fresh").contains("--set")
                .contains("users").contains("init");
    }

    @Test
    void aBadWorldExitsTwoBeforeTouchingTheDatabase() throws Exception {
        Path world = tmp.resolve("bad.json");
        Files.writeString(world, "{\"name\": \"bad world\"}");
        long start = System.nanoTime();
        assertThat(run("robot", "--world", world.toString(), "--db", "jdbc:mysql://127.0.0.1:1/none",
                "--out", tmp.resolve("never").toString())).isEqualTo(2);
        assertThat(System.nanoTime() - start).isLessThan(TimeUnit.SECONDS.toNanos(5));
        assertThat(err.toString()).contains("invalid world file").contains("checkpoints");
        assertThat(tmp.resolve("never")).doesNotExist();
    }

    @Test
    void badOptionsExitTwoNamingTheProblem() {
        assertThat(run("engine", "--db", "jdbc:mysql://127.0.0.1:1/none", "--strategy", "reckless")).isEqualTo(2);
        assertThat(run("engine", "--db", "mysql://127.0.0.1/none")).isEqualTo(2);
        assertThat(run("robot", "--world", Deployment.root().resolve("worlds/reference-arena.json").toString(),
                "--db", "jdbc:mysql://127.0.0.1:1/none", "--timing", "sometimes")).isEqualTo(2);
        assertThat(run("strategy", "--db", "jdbc:mysql://127.0.0.1:1/none", "--set", "reckless")).isEqualTo(2);
        assertThat(run("db", "users", "--db", "jdbc:mysql://127.0.0.1:1/none", "--engine-password", "a",
                "--robot-password", "b", "--engine-user", "bad name")).isEqualTo(2);
        assertThat(err.toString()).contains("unknown strategy 'reckless'; known: safety-first")
                .contains("--db must be a JDBC URL").contains("--timing must be sync or realtime")
                .contains("user names are");
    }

    @Test
    void dbUsersPrintsTheFilledScript() {
        assertThat(run("db", "users", "--db", "jdbc:mysql://mysql:3306/proactive", "--print",
                "--engine-password", "e", "--robot-password", "r")).isZero();
        assertThat(out.toString()).contains("CREATE USER IF NOT EXISTS 'proactive_engine'@'%' IDENTIFIED BY 'e'")
                .contains("GRANT SELECT ON `proactive`.engine_comments TO 'proactive_robot'@'%'")
                .doesNotContain("@DATABASE@");
    }

    @Test
    void dbUsersPrintShowsThePasswordsOnlyInTheStatementsThatSetThem() {
        assertThat(run("db", "users", "--db", "jdbc:mysql://mysql:3306/proactive", "--print",
                "--engine-password", "engine-Secret-1", "--robot-password", "robot-Secret-2")).isZero();
        List<String> lines = out.toString().lines().toList();
        assertThat(lines.get(0)).startsWith("-- ").contains("proactive_engine").contains("`proactive`");
        assertThat(lines).filteredOn(l -> l.contains("engine-Secret-1")).hasSize(2)
                .allSatisfy(l -> assertThat(l).matches("(CREATE|ALTER) USER .*'proactive_engine'.*"));
        assertThat(lines).filteredOn(l -> l.contains("robot-Secret-2")).hasSize(2)
                .allSatisfy(l -> assertThat(l).matches("(CREATE|ALTER) USER .*'proactive_robot'.*"));
        assertThat(lines).filteredOn(l -> l.startsWith("--")).noneSatisfy(l -> assertThat(l).containsAnyOf("Secret", "@"));
    }

    @Test
    void anUnreachableDatabaseIsWaitedForWithStatusLinesThenExitsThree() throws Exception {
        Path log = tmp.resolve("robot.log");
        Process robot = StartedProcesses.start(new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), Main.class.getName(), "robot",
                "--world", Deployment.root().resolve("worlds/reference-arena.json").toString(),
                "--db", "jdbc:mysql://127.0.0.1:1/proactive", "--wait-s", "2", "--out", tmp.resolve("out").toString())
                .redirectErrorStream(true).redirectOutput(log.toFile()));
        assertThat(robot.waitFor(60, TimeUnit.SECONDS)).isTrue();
        String text = Files.readString(log);
        assertThat(robot.exitValue()).as(text).isEqualTo(3);
        assertThat(text).contains("waiting for the database (attempt 1, retrying in 0.5 s, giving up after 2 s)")
                .contains("cannot reach the database at 127.0.0.1:1").contains("is the server running?")
                .contains("database not usable within 2 s").doesNotContain("Exception").doesNotContain("\tat ");
    }
}
