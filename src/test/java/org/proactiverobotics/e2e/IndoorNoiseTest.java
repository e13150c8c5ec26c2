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
 * {@code --noise indoor} (no GPS at all) and {@code realistic} through the real command line
 * (docs/sensors.md): indoors the engine knows where the robot is from its wheels, its inertial
 * unit and its scan matched against its own map, starting from the mission's initial pose.
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
    void indoorsTheReferenceMissionIsAccomplishedOnEitherLinkWithoutAnyGpsReading() throws Exception {
        for (String link : List.of("jdbc", "direct")) {
            Path outDir = tmp.resolve("indoor-" + link);
            int code = run("run", "--noise", "Indoor", "--link", link, "--quiet", "--out", outDir.toString());
            assertThat(code).as(err.toString()).isZero();
            assertThat(out.toString()).contains("indoor sensor noise", "MISSION_ACCOMPLISHED");
            JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"))).getAsJsonObject();
            assertThat(report.get("collisions").getAsInt()).isZero();
            assertThat(report.get("ruleFailures").getAsLong()).isZero();
            JsonObject pose = report.getAsJsonObject("poseError");
            assertThat(pose.get("meanM").getAsDouble()).as("indoors the estimate stays within 10 cm on average").isLessThan(0.10);
            List<String> trace = Files.readAllLines(outDir.resolve("trace.jsonl"));
            assertThat(trace).isNotEmpty().allSatisfy(line -> assertThat(line).contains("\"gps\":null"));
            // The other sensors still answer, the battery too (its readings are timed by the robot's other clocks).
            assertThat(trace).anySatisfy(line -> assertThat(line).containsPattern("\"headingRad\":-?[0-9]"));
            assertThat(trace.get(trace.size() - 1)).doesNotContain("\"seen\":{\"gps\":null,\"headingRad\":null");
            JsonObject last = JsonParser.parseString(trace.get(trace.size() - 1)).getAsJsonObject();
            assertThat(last.getAsJsonObject("seen").get("batteryPct").getAsDouble()).isLessThan(100.0);
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
}
