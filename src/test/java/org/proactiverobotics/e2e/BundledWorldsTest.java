package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.sim2d.WorldFiles;

/**
 * {@code --world NAME}: the worlds bundled in the jar by name on run, robot and validate; a file that exists
 * wins over a bundled name; a value that is neither exits 2 naming the bundled worlds; {@code worlds} lists them.
 */
class BundledWorldsTest extends CommandLineTest {

    private static final String NO_DB = "jdbc:mysql://127.0.0.1:1/none";

    @TempDir
    Path tmp;

    @Test
    void validateTakesABundledWorldsNameWithOrWithoutJson() {
        assertThat(run("validate", "--world", "low-battery")).as(err.toString()).isZero();
        assertThat(run("validate", "--world", "cluttered-arena.json")).as(err.toString()).isZero();
        assertThat(out.toString().lines().toList()).satisfiesExactly(
                l -> assertThat(l).startsWith("low-battery: valid (2 obstacles, 3 checkpoints"),
                l -> assertThat(l).startsWith("cluttered-arena: valid ("));
    }

    @Test
    void runTakesABundledWorldsName() throws Exception {
        Path outDir = tmp.resolve("out");
        assertThat(run("run", "--world", "obstacle-across-path", "--link", "direct", "--quiet", "--out", outDir.toString()))
                .as(err.toString()).isIn(0, 1);
        JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"), StandardCharsets.UTF_8))
                .getAsJsonObject();
        assertThat(report.get("world").getAsString()).isEqualTo("obstacle-across-path");
    }

    @Test
    void robotTakesABundledWorldsName() {
        // the world is checked first: reaching the option check means the name resolved
        assertThat(run("robot", "--world", "low-battery", "--db", NO_DB, "--robot-id", "-3")).isEqualTo(2);
        assertThat(err.toString()).contains("--robot-id must be >= 0").doesNotContain("low-battery");
    }

    @Test
    void aNameThatIsNeitherAFileNorBundledExitsTwoNamingTheBundledWorlds() {
        Path outDir = tmp.resolve("out");
        assertThat(run("run", "--world", "low-batery", "--quiet", "--out", outDir.toString())).isEqualTo(2);
        assertThat(run("robot", "--world", "low-batery", "--db", NO_DB, "--wait-s", "1", "--out", outDir.toString()))
                .isEqualTo(2);
        assertThat(run("validate", "--world", "low-batery")).isEqualTo(2);
        assertThat(outDir).doesNotExist();
        List<String> lines = err.toString().lines().toList();
        assertThat(lines).hasSize(3).allSatisfy(l -> assertThat(l)
                .startsWith("low-batery: no such file, and no bundled world of that name; bundled worlds: ")
                .contains(WorldFiles.bundledNames()));
    }

    @Test
    void aFileThatExistsWinsOverABundledName() throws Exception {
        // a file named like a bundled world, in the working directory, is the one loaded
        Path file = Path.of("low-battery");
        assertThat(file).doesNotExist();
        try {
            Files.writeString(file, Files.readString(worldsDir().resolve("reference-arena.json"), StandardCharsets.UTF_8)
                    .replace("\"reference-arena\"", "\"my-own\""));
            assertThat(run("validate", "--world", "low-battery")).as(err.toString()).isZero();
            assertThat(out.toString()).startsWith("my-own: valid (3 obstacles, 4 checkpoints");
        } finally {
            Files.deleteIfExists(file);
        }
    }

    @Test
    void worldsListsEveryBundledWorldWithItsCountsAndPurpose() {
        assertThat(run("worlds")).isZero();
        List<String> lines = out.toString().lines().toList();
        assertThat(lines.get(0)).contains("NAME").contains("CHECKPOINTS").contains("OBSTACLES");
        assertThat(lines.subList(1, lines.size())).hasSize(WorldFiles.bundledNames().size());
        assertThat(lines).anySatisfy(l -> assertThat(l).matches("low-battery +3 +2 +\\S.*recharge.*"));
        assertThat(lines).anySatisfy(l -> assertThat(l).matches("reference-arena \\(default\\) +4 +3 +\\S.*"));
    }

    @Test
    void runHelpNamesTheBundledWorlds() {
        assertThat(run("run", "--help")).isZero();
        assertThat(out.toString().replaceAll("\\s+", " ")).contains(String.join(", ", WorldFiles.bundledNames()));
    }

    private static Path worldsDir() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isRegularFile(p.resolve("worlds/reference-arena.json"))) {
                return p.resolve("worlds");
            }
        }
        throw new IllegalStateException("no worlds/ directory above " + Path.of("").toAbsolutePath());
    }
}
