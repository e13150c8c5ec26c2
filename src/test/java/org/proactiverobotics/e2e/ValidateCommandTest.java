package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code validate --world FILE} through the real command line (docs/command-line.md). */
class ValidateCommandTest extends CommandLineTest {

    /** The project's worlds/ directory, found from wherever the tests run. */
    private static Path worldsDir() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isRegularFile(p.resolve("worlds/reference-arena.json"))) {
                return p.resolve("worlds");
            }
        }
        throw new IllegalStateException("no worlds/ directory above " + Path.of("").toAbsolutePath());
    }

    @Test
    void aValidFileExitsZeroWithAOneLineSummary() {
        int code = run("validate", "--world", worldsDir().resolve("reference-arena.json").toString());
        assertThat(code).isZero();
        assertThat(out.toString().lines().toList())
                .containsExactly("reference-arena: valid (3 obstacles, 4 checkpoints, arena radius 5.0 m)");
        assertThat(err.toString()).isEmpty();
    }

    @Test
    void everyExampleWorldIsValid() throws Exception {
        List<Path> files;
        try (Stream<Path> s = Files.list(worldsDir())) {
            files = s.filter(p -> p.toString().endsWith(".json")).sorted().toList();
        }
        assertThat(files).hasSizeGreaterThanOrEqualTo(4);
        for (Path f : files) {
            assertThat(run("validate", "--world", f.toString())).as(f + ": " + err).isZero();
        }
        assertThat(out.toString().lines()).hasSize(files.size()).allMatch(l -> l.contains(": valid ("));
    }

    @Test
    void anInvalidFileExitsTwoWithEveryProblemOnStandardError(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("bad.json");
        Files.writeString(file, """
                { "name": "bad", "arena": { "radiusM": 0 }, "robot": { "x": 0, "y": 0, "headingDeg": 0, "speed": 1 },
                  "checkpoints": [ { "x": 1, "y": "one" } ], "rechargeStation": { "x": 0, "y": 0, "radiusM": 0.3 } }
                """);
        int code = run("validate", "--world", file.toString());
        assertThat(code).isEqualTo(2);
        assertThat(out.toString()).isEmpty();
        List<String> lines = err.toString().lines().toList();
        assertThat(lines.get(0)).contains("bad.json").contains("3 problems");
        assertThat(lines.subList(1, lines.size())).satisfiesExactly(
                l -> assertThat(l).startsWith("arena.radiusM: must be > 0"),
                l -> assertThat(l).startsWith("robot.speed: unknown key"),
                l -> assertThat(l).startsWith("checkpoints[0].y: expected a number"));
    }

    @Test
    void brokenJsonAndMissingFilesAreBadInput(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("broken.json");
        Files.writeString(file, "{ \"name\": ");
        assertThat(run("validate", "--world", file.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("malformed JSON");
        assertThat(run("validate", "--world", dir.resolve("nowhere.json").toString())).isEqualTo(2);
        assertThat(err.toString()).contains("no such file");
    }

    @Test
    void usageErrorsAreBadInputAndHelpWorks() {
        assertThat(run("validate")).isEqualTo(2);
        assertThat(err.toString()).contains("--world");
        assertThat(run("validate", "--help")).isZero();
        assertThat(out.toString()).contains("Usage:").contains("--world=FILE");
    }
}
