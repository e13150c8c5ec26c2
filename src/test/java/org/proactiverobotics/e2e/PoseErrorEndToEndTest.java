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
 * The pose error in report.json and results.csv (issue 32): the distance between the engine's pose
 * estimate (the Localisation scenario's) and the truth. With a GPS the estimate must be no worse
 * than the raw fix it had before the localiser existed.
 */
class PoseErrorEndToEndTest extends CommandLineTest {

    @TempDir
    Path tmp;

    /**
     * Small noise is 1 cm per GPS coordinate and 0.5° on the yaw, drawn afresh each step. Taken raw,
     * as the engine did before it had a localiser, the distance off is Rayleigh-distributed, mean
     * σ·√(π/2) = 1.253 cm (1.15–1.35 cm is ±6 sd of the mean over the ~1 500 iterations), the heading's
     * |N(0, 0.5°)| mean 6.96 mrad (6.1–7.8 mrad). The filter, predicting from odometry between fixes,
     * must do better than the lower end of both: no worse than the raw fix is the promise.
     */
    @Test
    void smallNoiseGivesAPoseErrorBelowTheRawFixes() throws Exception {
        Path outDir = tmp.resolve("small");
        assertThat(run("run", "--noise", "small", "--quiet", "--out", outDir.toString())).as(err.toString()).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"))).getAsJsonObject();
        JsonObject e = report.getAsJsonObject("poseError");
        assertThat(e.keySet()).containsExactly("meanM", "maxM", "meanHeadingRad", "maxHeadingRad", "samples");
        assertThat(e.get("meanM").getAsDouble()).isPositive().isLessThan(0.0115);
        assertThat(e.get("meanHeadingRad").getAsDouble()).isPositive().isLessThan(0.0061);
        assertThat(e.get("maxM").getAsDouble()).isGreaterThan(e.get("meanM").getAsDouble()).isLessThan(0.05);
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
     * Without noise the GPS, the inertial unit and the wheels are exact; what remains is how far the
     * filter's model of a differential drive (an arc per step) is from the physics: millimetres.
     */
    @Test
    void withoutNoiseThePoseEstimateIsTheTruthToMillimetres() {
        Missions.Run run = Missions.onH2("reference-arena");
        PoseError e = run.report().poseError();
        assertThat(e).isNotNull();
        assertThat(e.samples()).isGreaterThan(run.report().engineIterations() * 9 / 10);
        assertThat(e.meanM()).isLessThan(0.005);
        assertThat(e.maxM()).isLessThan(0.02);
        assertThat(e.meanHeadingRad()).isLessThan(0.002);
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
                assertThat(e.get("meanM").getAsDouble()).as(row.get("noise"))
                        .isLessThan(row.get("noise").equals("realistic") ? 0.10 : 0.005);
            }
        }
    }
}
