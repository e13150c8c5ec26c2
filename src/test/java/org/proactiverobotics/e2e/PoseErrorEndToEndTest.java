package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.mission.PoseError;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The pose error in report.json and results.csv (issue 32): the engine's pose today is its newest
 * GPS reading and inertial-unit heading, so the error is the sensors' noise and nothing else. It
 * is the baseline a localiser will be compared against.
 */
class PoseErrorEndToEndTest extends CommandLineTest {

    @TempDir
    Path tmp;

    /**
     * Small noise is 1 cm per GPS coordinate and 0.5° on the yaw, drawn afresh each step. The
     * distance off is then Rayleigh-distributed, mean σ·√(π/2) = 1.253 cm, sd 0.655 cm; over the
     * ~1 480 iterations of the reference mission the sample mean's sd is 0.017 cm, so 1.15–1.35 cm
     * is ±6 sd. The heading's error is |N(0, 0.5°)|: mean σ·√(2/π) = 6.96 mrad, sd of the sample
     * mean 0.14 mrad, so 6.1–7.8 mrad is ±6 sd. An error larger than that means the pose the engine
     * steered by lags or is taken from the wrong place; smaller, that the noise is not reaching it.
     */
    @Test
    void smallNoiseGivesThePoseErrorOfTheGpsAndTheInertialUnitAlone() throws Exception {
        Path outDir = tmp.resolve("small");
        assertThat(run("run", "--noise", "small", "--quiet", "--out", outDir.toString())).as(err.toString()).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"))).getAsJsonObject();
        JsonObject e = report.getAsJsonObject("poseError");
        assertThat(e.keySet()).containsExactly("meanM", "maxM", "meanHeadingRad", "maxHeadingRad", "samples");
        assertThat(e.get("meanM").getAsDouble()).isBetween(0.0115, 0.0135);
        assertThat(e.get("meanHeadingRad").getAsDouble()).isBetween(0.0061, 0.0078);
        // the worst of ~1 480 Rayleigh draws is about σ·√(2 ln n) = 3.8 cm; a 10 cm one is a fault, not noise
        assertThat(e.get("maxM").getAsDouble()).isGreaterThan(e.get("meanM").getAsDouble()).isLessThan(0.10);
        assertThat(e.get("maxHeadingRad").getAsDouble()).isGreaterThan(e.get("meanHeadingRad").getAsDouble())
                .isLessThan(Math.toRadians(5 * 0.5));

        // one sample per iteration from the first in which the engine had a pose: the trace's lines from
        // its first belief on, and the same error recomputed from their poses at the trace's millimetre
        List<JsonObject> lines = Files.readAllLines(outDir.resolve("trace.jsonl")).stream()
                .map(l -> JsonParser.parseString(l).getAsJsonObject()).toList();
        JsonObject belief = null;
        long samples = 0;
        double sumM = 0;
        for (JsonObject line : lines) {
            if (line.has("belief") && line.getAsJsonObject("belief").has("xM")) {
                belief = line.getAsJsonObject("belief");
            }
            if (belief != null) {
                JsonObject pose = line.getAsJsonObject("pose");
                samples++;
                sumM += Math.hypot(belief.get("xM").getAsDouble() - pose.get("xM").getAsDouble(),
                        belief.get("yM").getAsDouble() - pose.get("yM").getAsDouble());
            }
        }
        assertThat(e.get("samples").getAsLong()).isEqualTo(samples).isGreaterThan(lines.size() * 9L / 10);
        assertThat(e.get("meanM").getAsDouble()).isCloseTo(sumM / samples, within(0.0005));
    }

    /**
     * Without noise the error is the reading's age alone, and that age is nothing: the robot answers
     * the engine's sensor requests in the same control step, just before the iteration, and the world
     * does not move in between. So the figures are zero, over as many samples as with noise.
     */
    @Test
    void withoutNoiseThePoseTheEngineHadIsTheTruth() {
        PoseError e = Missions.onH2("reference-arena").report().poseError();
        assertThat(e).isNotNull();
        assertThat(e.samples()).isGreaterThan(Missions.onH2("reference-arena").report().engineIterations() * 9 / 10);
        assertThat(List.of(e.meanM(), e.maxM(), e.meanHeadingRad(), e.maxHeadingRad())).containsOnly(0.0);
    }

    /** results.csv's four new columns come last, and hold report.json's figures, value for value. */
    @Test
    void resultsCsvHasThePoseErrorOfEachMissionsReport() throws Exception {
        WorldSpec shortWorld = Missions.shortReferenceArena("short-limit", 3.0);
        Path world = Files.writeString(tmp.resolve("short-limit.json"), WorldJson.of(shortWorld));
        Path out = tmp.resolve("sweep");
        assertThat(run("sweep", "--worlds", world.toString(), "--noise", "none,realistic", "--link", "direct",
                "--jobs", "1", "--out", out.toString())).as(err.toString()).isEqualTo(1);
        try (Reader in = Files.newBufferedReader(out.resolve("results.csv"), StandardCharsets.UTF_8);
             CSVParser csv = CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in)) {
            assertThat(csv.getHeaderNames()).containsExactly("world", "strategy", "noise", "seed", "outcome", "success",
                    "checkpointsReached", "checkpointsTotal", "simTimeS", "wallTimeS", "distanceM", "collisions",
                    "minBattery", "recharges", "worldKind", "reason", "mission", "poseErrorMeanM", "poseErrorMaxM",
                    "headingErrorMeanRad", "headingErrorMaxRad");
            List<CSVRecord> rows = csv.getRecords();
            assertThat(rows).hasSize(2);
            for (CSVRecord row : rows) {
                JsonObject e = JsonParser.parseString(Files.readString(out.resolve(row.get("mission")).resolve("report.json")))
                        .getAsJsonObject().getAsJsonObject("poseError");
                assertThat(Double.parseDouble(row.get("poseErrorMeanM"))).isEqualTo(e.get("meanM").getAsDouble());
                assertThat(Double.parseDouble(row.get("poseErrorMaxM"))).isEqualTo(e.get("maxM").getAsDouble());
                assertThat(Double.parseDouble(row.get("headingErrorMeanRad"))).isEqualTo(e.get("meanHeadingRad").getAsDouble());
                assertThat(Double.parseDouble(row.get("headingErrorMaxRad"))).isEqualTo(e.get("maxHeadingRad").getAsDouble());
                assertThat(e.get("meanM").getAsDouble() > 0).as(row.get("noise")).isEqualTo(row.get("noise").equals("realistic"));
            }
        }
    }
}
