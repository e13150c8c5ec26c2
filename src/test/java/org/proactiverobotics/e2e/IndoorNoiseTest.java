package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * {@code --noise indoor} (no GPS at all) and {@code realistic} through the real command line (docs/sensors.md):
 * without a localiser the engine cannot navigate indoors, so the mission must end safely, not crash.
 */
class IndoorNoiseTest extends CommandLineTest {

    @TempDir
    Path tmp;

    /** The reference arena with an 8 s time limit. */
    private Path shortWorld() throws IOException {
        WorldSpec s = Missions.shortReferenceArena("short-indoor", 8.0);
        Path file = tmp.resolve("short-indoor.json");
        Files.writeString(file, WorldJson.of(s));
        return file;
    }

    @Test
    void indoorsTheMissionEndsSafelyOnEitherLinkWithNoGpsReadingAtAll() throws Exception {
        Path world = shortWorld();
        for (String link : List.of("jdbc", "direct")) {
            Path outDir = tmp.resolve("indoor-" + link);
            int code = run("run", "--world", world.toString(), "--noise", "Indoor", "--link", link, "--quiet",
                    "--out", outDir.toString());
            assertThat(code).as(err.toString()).isEqualTo(1); // mission failed: a normal outcome, not a crash (3)
            assertThat(out.toString()).contains("indoor sensor noise", "TIME_LIMIT");
            JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"))).getAsJsonObject();
            assertThat(report.get("outcome").getAsString()).isEqualTo("TIME_LIMIT");
            assertThat(report.get("collisions").getAsInt()).isZero();
            assertThat(report.get("ruleFailures").getAsLong()).isZero();
            // Without a position the engine never sends the robot anywhere: it stays where it started.
            assertThat(report.get("distanceM").getAsDouble()).isLessThan(0.01);
            assertThat(report.has("poseError")).as("the engine never had a pose to measure").isFalse();
            List<String> trace = Files.readAllLines(outDir.resolve("trace.jsonl"));
            assertThat(trace).isNotEmpty().allSatisfy(line -> assertThat(line).contains("\"gps\":null"));
            // The other sensors still answer.
            assertThat(trace).anySatisfy(line -> assertThat(line).containsPattern("\"headingRad\":-?[0-9]"));
            assertThat(outDir.resolve("replay.html")).exists();
            out.getBuffer().setLength(0);
        }
    }

    @Test
    void realisticIsTheSameRunTwiceAndItsErrorsShow() throws Exception {
        Path world = shortWorld();
        Path a = tmp.resolve("a");
        Path b = tmp.resolve("b");
        Path none = tmp.resolve("none");
        for (Path dir : List.of(a, b)) {
            run("run", "--world", world.toString(), "--noise", "realistic", "--link", "direct", "--quiet", "--out", dir.toString());
        }
        run("run", "--world", world.toString(), "--link", "direct", "--quiet", "--out", none.toString());
        assertThat(Files.readString(a.resolve("trace.jsonl"))).isEqualTo(Files.readString(b.resolve("trace.jsonl")))
                .isNotEqualTo(Files.readString(none.resolve("trace.jsonl")));
        assertThat(deterministic(a.resolve("report.json"))).isEqualTo(deterministic(b.resolve("report.json")));
    }

    @Test
    void anUnknownLevelNamesIndoorAmongTheLevelsAndWritesNothing() {
        Path outDir = tmp.resolve("never");
        assertThat(run("run", "--noise", "outdoor", "--out", outDir.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("outdoor").contains("none, small, realistic, indoor");
        assertThat(outDir).doesNotExist();
    }

    private static JsonObject deterministic(Path report) throws IOException {
        JsonObject o = JsonParser.parseString(Files.readString(report)).getAsJsonObject();
        o.remove("wallTimeS");
        o.remove("realTimeFactor");
        o.remove("timing");
        return o;
    }
}
