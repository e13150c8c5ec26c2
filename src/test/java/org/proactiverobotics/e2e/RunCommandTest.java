package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code run} through the real command line (docs/command-line.md, docs/report.md). */
class RunCommandTest extends CommandLineTest {

    @TempDir
    Path tmp;

    @Test
    void theDefaultMissionWritesTheReportTraceAndPicture() throws Exception {
        Path outDir = tmp.resolve("run");
        int code = run("run", "--out", outDir.toString(), "--quiet");
        assertThat(code).as(err.toString()).isZero();
        assertThat(out.toString()).contains("MISSION_ACCOMPLISHED").contains(outDir.resolve("report.json").toString());
        JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"))).getAsJsonObject();
        assertThat(report.keySet()).contains("world", "success", "outcome", "checkpointsReached", "checkpointsTotal",
                "simTimeS", "wallTimeS", "controlSteps", "engineIterations", "distanceM", "collisions", "minBattery",
                "recharges", "commandWins");
        assertThat(report.get("strategy").getAsString()).isEqualTo("safety-first");
        assertThat(report.get("ruleFailures").getAsLong()).isZero();
        assertThat(report.get("world").getAsString()).isEqualTo("reference-arena");
        assertThat(report.get("success").getAsBoolean()).isTrue();
        assertThat(report.getAsJsonObject("commandWins").keySet()).contains("ReachDestination", "ObstacleAvoidance");
        // The command line runs the same mission as the library, to the step.
        assertThat(report.get("controlSteps").getAsLong())
                .isEqualTo(Missions.onH2("reference-arena").report().controlSteps());
        assertThat(Files.readString(outDir.resolve("trajectory.svg"))).startsWith("<?xml").contains("<svg");
        assertThat(Files.readAllLines(outDir.resolve("trace.jsonl"))).hasSize((int) report.get("engineIterations").getAsLong() - 2);
    }

    @Test
    void anInvalidWorldExitsTwoAndWritesNothing() throws Exception {
        Path world = tmp.resolve("bad.json");
        Files.writeString(world, "{\"name\": \"bad world\", \"arena\": {\"radiusM\": -1}}");
        Path outDir = tmp.resolve("never");
        assertThat(run("run", "--world", world.toString(), "--out", outDir.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("name").contains("arena.radiusM").contains("checkpoints");
        assertThat(outDir).doesNotExist();
    }

    @Test
    void anUnknownStrategyExitsTwoNamingTheKnownOnesAndWritesNothing() {
        Path outDir = tmp.resolve("never");
        assertThat(run("run", "--strategy", "yolo", "--out", outDir.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("yolo").contains("safety-first").contains("destination-first");
        assertThat(outDir).doesNotExist();
    }

    @Test
    void aNegativeRobotIdIsBadInputAndWritesNothing() {
        Path outDir = tmp.resolve("never");
        assertThat(run("run", "--robot-id", "-4", "--out", outDir.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--robot-id");
        assertThat(outDir).doesNotExist();
    }

    @Test
    void anUnknownOptionIsAUsageErrorWithExitTwoThatSuggestsTheOptionMeantNotTheWholeUsage() {
        assertThat(run("run", "--wrld", "x.json")).isEqualTo(2);
        assertThat(err.toString()).isEqualTo("unknown option --wrld\nDid you mean: --world?\nSee 'proactive run --help'.\n");
        err.getBuffer().setLength(0);
        assertThat(run("swep", "--worlds", "reference-arena")).isEqualTo(2);
        assertThat(err.toString()).isEqualTo("unknown command swep\nDid you mean: sweep?\nSee 'proactive --help'.\n");
        assertThat(out.toString()).isEmpty();
    }

    @Test
    void aFolderThatHoldsSomethingIsRefusedUntouchedAndForceWritesIntoIt() throws Exception {
        Path outDir = Files.createDirectories(tmp.resolve("earlier"));
        Files.writeString(outDir.resolve("report.json"), "an earlier run's");
        assertThat(run("run", "--link", "direct", "--quiet", "--out", outDir.toString())).isEqualTo(2);
        assertThat(err.toString()).isEqualTo("--out " + outDir
                + " exists and is not empty: give --force to write into it anyway, or another folder\n");
        assertThat(out.toString()).isEmpty();
        try (var files = Files.list(outDir)) {
            assertThat(files.map(p -> p.getFileName().toString()).toList()).containsExactly("report.json");
        }
        assertThat(Files.readString(outDir.resolve("report.json"))).isEqualTo("an earlier run's");

        // with --force, and names in any case (as a user types them)
        assertThat(run("run", "--link", "Direct", "--noise", "Realistic", "--strategy", "Safety-First", "--quiet", "--force",
                "--out", outDir.toString())).as(err.toString()).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"))).getAsJsonObject();
        assertThat(report.get("strategy").getAsString()).isEqualTo("safety-first");
        assertThat(out.toString()).contains("the direct in-process link", "realistic sensor noise", "MISSION_ACCOMPLISHED");
        assertThat(outDir.resolve("replay.html")).exists();
    }

    @Test
    void aJdbcUrlNoDriverAcceptsIsBadInputAndWritesNothing() {
        Path outDir = tmp.resolve("never");
        assertThat(run("run", "--db", "jdbc:nosuchdb://somewhere/x", "--out", outDir.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("jdbc:nosuchdb://somewhere/x").doesNotContain("Exception");
        assertThat(outDir).doesNotExist();
    }

    @Test
    void theSummarySaysOneRechargeInTheSingular() {
        assertThat(run("run", "--world", "low-battery", "--link", "direct", "--quiet", "--out", tmp.resolve("low").toString()))
                .as(err.toString()).isZero();
        assertThat(out.toString()).contains(", 0 collisions, ").contains(", 1 recharge\n").doesNotContain("1 recharges");
    }

    @Test
    void helpAndVersionExitZero() {
        assertThat(run("run", "--help")).isZero();
        assertThat(out.toString()).contains("--world").contains("--strategy").contains("safety-first").contains("--db");
        assertThat(run("--version")).isZero();
        assertThat(out.toString()).contains("proactive-robotics");
    }
}
