package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Bad input on the command line (issue 7): malformed worlds of several kinds and bad options of
 * every command each give exit code 2 with the reason on standard error, before any database is
 * touched (the database named here does not exist and --wait-s is short: reaching it would be exit
 * 3) and without writing anything (no output directory). RunCommandTest, ValidateCommandTest and
 * DeployCommandsTest hold the first cases of each; these are the rest.
 */
class BadInputTest extends CommandLineTest {

    /** A database that is not there: a command that got as far as waiting for it would exit 3, not 2. */
    private static final String NO_DB = "jdbc:mysql://127.0.0.1:1/none";
    private static final String CHECKS = "\"robot\": {\"x\": 0, \"y\": -2, \"headingDeg\": 90}, "
            + "\"rechargeStation\": {\"x\": -2, \"y\": 0, \"radiusM\": 0.3}";

    @TempDir
    Path tmp;

    static Stream<Arguments> malformedWorlds() {
        return Stream.of(
                Arguments.of("binary", null, "cannot read"),
                Arguments.of("empty", "", "malformed JSON"),
                Arguments.of("array", "[1, 2, 3]", "expected a JSON object"),
                Arguments.of("truncated", "{\"name\": \"x\", \"arena\": {\"radiusM\"", "malformed JSON"),
                Arguments.of("missing-comma", "{\"name\": \"x\", \"arena\": {\"radiusM\": 3}\n  \"robot\": 1}",
                        "malformed JSON: an object is not closed, or a ',' is missing between its entries (line 2, column 4, in arena)"),
                Arguments.of("unquoted", "{\"name\": x}", "malformed JSON: not strict JSON"),
                Arguments.of("nan-literal", "{\"name\": \"x\", \"arena\": {\"radiusM\": NaN}, " + CHECKS
                        + ", \"checkpoints\": [{\"x\": 1, \"y\": 1}]}", "malformed JSON"),
                Arguments.of("sql-name-overflow", "{\"name\": \"x'; DROP TABLE checkpoints; --\", \"arena\": {\"radiusM\": 1e400}, "
                        + CHECKS + ", \"checkpoints\": []}", "arena.radiusM: must be a finite number"),
                Arguments.of("unicode-and-unknown-shape", "{\"name\": \"w\u00f6rld\u2603\", \"timeStepMs\": 0, \"arena\": {\"radiusM\": 3}, "
                        + CHECKS + ", \"obstacles\": [{\"shape\": \"hexagon\", \"x\": 0, \"y\": 0}], "
                        + "\"checkpoints\": [{\"x\": 1, \"y\": 1}]}", "obstacles[0].shape"),
                Arguments.of("outside-and-inside", "{\"name\": \"x\", \"arena\": {\"radiusM\": 3}, " + CHECKS
                        + ", \"obstacles\": [{\"shape\": \"circle\", \"x\": 1, \"y\": 1, \"radiusM\": 0.5}], "
                        + "\"checkpoints\": [{\"x\": 1, \"y\": 1}, {\"x\": 9, \"y\": 0}]}", "checkpoints[1]"),
                Arguments.of("wrong-types", "{\"name\": 7, \"arena\": \"big\", \"robot\": [], \"checkpoints\": {}, "
                        + "\"rechargeStation\": null}", "arena"),
                Arguments.of("directory", null, "cannot read"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("malformedWorlds")
    void aMalformedWorldIsRefusedByValidateRunAndRobotWithExitTwoAndNothingWritten(String kind, String json, String problem)
            throws Exception {
        Path world = tmp.resolve(kind + ".json");
        if (kind.equals("binary")) {
            Files.write(world, new byte[] {0, (byte) 0xff, (byte) 0xfe, 'g', (byte) 0xc3});
        } else if (kind.equals("directory")) {
            Files.createDirectories(world);
        } else {
            Files.writeString(world, json);
        }
        assertThat(run("validate", "--world", world.toString())).as(err.toString()).isEqualTo(2);
        assertThat(err.toString()).contains("invalid world file").contains(problem);
        List<String> lines = err.toString().lines().toList();
        if (lines.size() == 1) {
            assertThat(lines.get(0)).as("one problem, one line").contains(": invalid world file: ");
        } else {
            assertThat(lines.get(0)).as("several problems: a header counting them, then one line each")
                    .endsWith(": invalid world file, " + (lines.size() - 1) + " problems:");
        }

        Path runOut = tmp.resolve("run-out");
        assertThat(run("run", "--world", world.toString(), "--out", runOut.toString(), "--quiet")).isEqualTo(2);
        Path robotOut = tmp.resolve("robot-out");
        long start = System.nanoTime();
        assertThat(run("robot", "--world", world.toString(), "--db", NO_DB, "--wait-s", "1", "--out", robotOut.toString()))
                .isEqualTo(2);
        assertThat(System.nanoTime() - start).isLessThan(TimeUnit.SECONDS.toNanos(5));
        assertThat(runOut).doesNotExist();
        assertThat(robotOut).doesNotExist();
        assertThat(out.toString()).isEmpty();
        assertThat(err.toString()).doesNotContain("\tat ").doesNotContain("Exception in")
                .doesNotContain("setStrictness").doesNotContain("LENIENT").doesNotContain("http"); // Gson's advice and link
    }

    static Stream<Arguments> badOptions() {
        String world = Deployment.root().resolve("worlds/reference-arena.json").toString();
        String sql = "'; DROP TABLE checkpoints; --";
        String huge = "x".repeat(100_000);
        List<Arguments> cases = new ArrayList<>(List.of(
                // the command line itself
                Arguments.of(List.of(), "Missing subcommand"),
                Arguments.of(List.of("fly"), "fly"),
                // run
                Arguments.of(List.of("run", "--world", "/nowhere/at/all.json"), "no such file"),
                Arguments.of(List.of("run", "--strategy", sql), "unknown strategy"),
                Arguments.of(List.of("run", "--strategy", huge), "unknown strategy"),
                Arguments.of(List.of("run", "--strategy", "SAFETY-LAST"), "unknown strategy"),
                Arguments.of(List.of("run", "--wrld", "x.json"), "Did you mean: --world?"),
                Arguments.of(List.of("run", "--noise", "Loud"), "unknown noise level Loud"),
                Arguments.of(List.of("run", "--link", "pigeon"), "pigeon"),
                Arguments.of(List.of("run", "--quiet=maybe"), "maybe"),
                // validate
                Arguments.of(List.of("validate", "--world", world, "extra"), "extra"),
                Arguments.of(List.of("validate", "--world"), "--world"),
                // engine
                Arguments.of(List.of("engine"), "--db"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--robot-id", "-1"), "--robot-id must be >= 0"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--robot-id", "99999999999"), "99999999999"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--robot-id", "1; DROP TABLE strategy"), "--robot-id"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--strategy", sql), "unknown strategy"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--max-speed-mps", "NaN"), "--max-speed-mps"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--max-speed-mps", "Infinity"), "--max-speed-mps"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--axle-width-m", "-0.2"), "--axle-width-m"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--period-ms", "0"), "--period-ms"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--log-every", "0"), "--log-every"),
                Arguments.of(List.of("engine", "--db", NO_DB, "--wait-s", "-1"), "--wait-s"),
                Arguments.of(List.of("engine", "--db", sql), "--db must be a JDBC URL"),
                // robot
                Arguments.of(List.of("robot", "--db", NO_DB), "--world"),
                Arguments.of(List.of("robot", "--world", world, "--db", NO_DB, "--robot-id", "-3"), "--robot-id must be >= 0"),
                Arguments.of(List.of("robot", "--world", world, "--db", NO_DB, "--robot-id", "2147483648"), "2147483648"),
                Arguments.of(List.of("robot", "--world", world, "--db", NO_DB, "--real-time-factor", "0"), "--real-time-factor"),
                Arguments.of(List.of("robot", "--world", world, "--db", NO_DB, "--real-time-factor", "NaN"), "--real-time-factor"),
                Arguments.of(List.of("robot", "--world", world, "--db", NO_DB, "--real-time-factor", "-Infinity"),
                        "--real-time-factor"),
                Arguments.of(List.of("robot", "--world", world, "--db", NO_DB, "--timing", "SYNC; --"), "--timing"),
                Arguments.of(List.of("robot", "--world", world, "--db", NO_DB, "--log-every", "-5"), "--log-every"),
                Arguments.of(List.of("robot", "--world", world, "--db", "jdbc"), "--db must be a JDBC URL"),
                // strategy
                Arguments.of(List.of("strategy"), "--db"),
                Arguments.of(List.of("strategy", "--db", NO_DB, "--set", sql), "unknown strategy"),
                Arguments.of(List.of("strategy", "--db", NO_DB, "--set", "\u2603"), "unknown strategy"),
                Arguments.of(List.of("strategy", "--db", NO_DB, "--robot-id", "one"), "--robot-id"),
                Arguments.of(List.of("strategy", "--db", "mysql://x"), "--db must be a JDBC URL"),
                // db
                Arguments.of(List.of("db", "drop-everything"), "drop-everything"),
                Arguments.of(List.of("db", "users", "--db", NO_DB, "--engine-password", "e", "--robot-password", "r",
                        "--robot-user", "robot'; DROP USER root; --"), "user names are")));
        return cases.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badOptions")
    void aBadOptionExitsTwoWithTheReasonBeforeTouchingTheDatabase(List<String> args, String reason) {
        long start = System.nanoTime();
        assertThat(run(args.toArray(String[]::new))).as(err.toString()).isEqualTo(2);
        assertThat(System.nanoTime() - start).isLessThan(TimeUnit.SECONDS.toNanos(5));
        String text = err.toString();
        assertThat(text).contains(reason.length() > 200 ? reason.substring(0, 200) : reason)
                .doesNotContain("\tat ").doesNotContain("Exception in");
    }

    @Test
    void anOutputThatIsAFileIsBadInputSaidSoAndTheFileIsLeftAlone() throws Exception {
        Path file = Files.writeString(tmp.resolve("report-here"), "keep me");
        String world = Deployment.root().resolve("worlds/reference-arena.json").toString();
        assertThat(run("robot", "--world", world, "--db", NO_DB, "--wait-s", "1", "--out", file.toString())).isEqualTo(2);
        assertThat(run("run", "--out", file.toString(), "--quiet")).isEqualTo(2);
        assertThat(err.toString()).isEqualTo(("--out " + file + " is a file, not a folder: give a folder that does not exist"
                + " yet or is empty\n").repeat(2));
        err.getBuffer().setLength(0);
        assertThat(run("run", "--out", file.resolve("sub").toString(), "--quiet")).isEqualTo(2);
        assertThat(err.toString()).isEqualTo("--out " + file.resolve("sub") + ": " + file.toAbsolutePath()
                + " is a file, not a folder: give a folder that does not exist yet\n");
        assertThat(Files.readString(file)).isEqualTo("keep me");
        assertThat(out.toString()).isEmpty();
    }

    @Test
    void aRobotOutputThatHoldsSomethingIsRefusedBeforeTheDatabaseUnlessForced() throws Exception {
        Path full = Files.createDirectories(tmp.resolve("full"));
        Files.writeString(full.resolve("report.json"), "an earlier robot's");
        String world = Deployment.root().resolve("worlds/reference-arena.json").toString();
        assertThat(run("robot", "--world", world, "--db", NO_DB, "--wait-s", "1", "--out", full.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--out " + full + " exists and is not empty", "--force");
        assertThat(Files.readString(full.resolve("report.json"))).isEqualTo("an earlier robot's");
        // with --force it goes on to the database, which is not there: exit 3, the folder as it was
        assertThat(run("robot", "--world", world, "--db", NO_DB, "--wait-s", "0", "--force", "--out", full.toString()))
                .isEqualTo(3);
        assertThat(Files.readString(full.resolve("report.json"))).isEqualTo("an earlier robot's");
    }
}
