package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.stream.Collectors;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.app.sweep.MissionResult;
import org.proactiverobotics.app.sweep.MissionRunner;
import org.proactiverobotics.app.sweep.ResultsCsv;
import org.proactiverobotics.app.sweep.Sweep;
import org.proactiverobotics.app.sweep.SweepMission;
import org.proactiverobotics.app.sweep.SweepProgress;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * {@code sweep} (issue 13): every combination runs as {@code run} would run it alone, whatever
 * {@code --jobs}; a mission past its time limit or one that throws is a failed row and the sweep
 * goes on; a stop keeps the rows done; bad input exits 2 with nothing written. Small missions on
 * the direct link, to keep the suite fast.
 */
class SweepCommandTest extends CommandLineTest {

    @TempDir
    Path tmp;

    /** The reference arena with a 3 s time limit: a mission that must end TIME_LIMIT, quickly. */
    private Path shortWorld() throws IOException {
        WorldSpec s = Missions.shortReferenceArena("short-limit", 3.0);
        Path dir = Files.createDirectories(tmp.resolve("worlds"));
        Files.writeString(dir.resolve("short-limit.json"), WorldJson.of(s));
        return dir;
    }

    @Test
    void everyMissionGivesTheReportRunGivesAloneWhateverTheJobs() throws Exception {
        Path worlds = shortWorld();
        Path two = tmp.resolve("two-jobs");
        assertThat(run("sweep", "--worlds", "reference-arena", worlds.toString(), "--noise", "none,small",
                "--link", "direct", "--jobs", "2", "--out", two.toString())).as(err.toString()).isEqualTo(1);
        assertThat(out.toString()).contains("Sweep of 4 missions (2 worlds x 1 strategy x 2 noise levels x each world's seed)");
        Map<String, CSVRecord> rows = rows(two.resolve("results.csv"));
        assertThat(rows).hasSize(4);
        assertThat(rows.get("0001-reference-arena-safety-first-none-s1").get("outcome")).isEqualTo("MISSION_ACCOMPLISHED");
        CSVRecord limited = rows.get("0003-short-limit-safety-first-none-s7");
        assertThat(limited.get("outcome")).isEqualTo("TIME_LIMIT");
        assertThat(limited.get("success")).isEqualTo("false");
        assertThat(limited.get("reason")).contains("maxSimTimeS");

        for (CSVRecord row : rows.values()) { // each mission alone in run, from the world its folder keeps
            Path folder = two.resolve(row.get("mission"));
            Path alone = tmp.resolve("run-" + row.get("mission"));
            int code = run("run", "--world", folder.resolve("world.json").toString(), "--noise", row.get("noise"),
                    "--strategy", row.get("strategy"), "--link", "direct", "--out", alone.toString(), "--quiet");
            assertThat(code).as(err.toString()).isEqualTo(row.get("success").equals("true") ? 0 : 1);
            assertThat(deterministic(folder.resolve("report.json"))).isEqualTo(deterministic(alone.resolve("report.json")));
            assertThat(Files.readString(folder.resolve("trace.jsonl"))).isEqualTo(Files.readString(alone.resolve("trace.jsonl")));
        }
        // the same rows with one job at a time (the order of the rows may differ, not their content), names in any case
        Path one = tmp.resolve("one-job");
        assertThat(run("sweep", "--worlds", "reference-arena", worlds.toString(), "--noise", "None,SMALL,small",
                "--strategies", "Safety-First", "--link", "Direct", "--jobs", "1", "--out", one.toString())).isEqualTo(1);
        assertThat(withoutWallTime(rows(one.resolve("results.csv")))).isEqualTo(withoutWallTime(rows));
        // noise changes the run: the small-noise mission is not the noiseless one
        assertThat(deterministic(two.resolve("0001-reference-arena-safety-first-none-s1/report.json")))
                .isNotEqualTo(deterministic(two.resolve("0002-reference-arena-safety-first-small-s1/report.json")));

        String summary = Files.readString(two.resolve("summary.html"));
        assertThat(summary).contains("0003-short-limit-safety-first-none-s7/replay.html", "short-limit", "TIME_LIMIT")
                .doesNotContain("<script src", "<link ", "src=\"http", "href=\"http", "url(http", "@import");
    }

    @Test
    void aSeedListRunsEachSeedOnAnEmbeddedDatabaseOfItsOwnAsRunDoes() throws Exception {
        Path worlds = shortWorld();
        Path out = tmp.resolve("seeds");
        assertThat(run("sweep", "--worlds", worlds.toString(), "--seeds", "1..2", "--noise", "realistic",
                "--strategies", "safety-first,battery-first", "--out", out.toString())).as(err.toString()).isEqualTo(1);
        Map<String, CSVRecord> rows = rows(out.resolve("results.csv"));
        assertThat(rows.keySet()).containsExactly("0001-short-limit-safety-first-realistic-s1",
                "0002-short-limit-safety-first-realistic-s2", "0003-short-limit-battery-first-realistic-s1",
                "0004-short-limit-battery-first-realistic-s2");
        JsonObject report = JsonParser.parseString(Files.readString(out.resolve("0002-short-limit-safety-first-realistic-s2/report.json")))
                .getAsJsonObject();
        assertThat(report.get("database").getAsString()).isEqualTo("h2");
        Path alone = tmp.resolve("alone");
        run("run", "--world", out.resolve("0002-short-limit-safety-first-realistic-s2/world.json").toString(),
                "--noise", "realistic", "--out", alone.toString(), "--quiet");
        assertThat(deterministic(out.resolve("0002-short-limit-safety-first-realistic-s2/report.json")))
                .isEqualTo(deterministic(alone.resolve("report.json")));
        assertThat(deterministic(out.resolve("0001-short-limit-safety-first-realistic-s1/report.json")))
                .isNotEqualTo(deterministic(out.resolve("0002-short-limit-safety-first-realistic-s2/report.json")));
    }

    @Test
    void aMissionThatThrowsIsAFailedRowWithItsReasonAndTheSweepGoesOn() throws Exception {
        WorldSpec world = WorldFiles.load(shortWorld().resolve("short-limit.json"));
        List<SweepMission> missions = List.of(
                new SweepMission(1, world, "short-limit", Strategy.named("safety-first"), NoiseLevel.NONE, 7),
                new SweepMission(2, world, "short-limit", Strategy.named("destination-first"), NoiseLevel.NONE, 7));
        Path out = Files.createDirectories(tmp.resolve("faults"));
        Sweep sweep = new Sweep(missions, out, 2);
        MissionRunner runner = new MissionRunner(MissionOptions.Link.DIRECT, ScenarioPlugins.none(), (report, file) -> {
            if (report.strategy().equals("safety-first")) {
                throw new IOException("disk full (injected)");
            }
            Files.writeString(file, "{}");
        }, sweep::isStopped);
        List<MissionResult> results;
        try (ResultsCsv csv = new ResultsCsv(out.resolve("results.csv"));
             SweepProgress progress = SweepProgress.start(2, false, new java.io.PrintWriter(new java.io.StringWriter()))) {
            results = sweep.run(runner, csv, progress);
        }
        assertThat(results).extracting(MissionResult::outcome).containsExactly(MissionResult.ERROR, "TIME_LIMIT");
        assertThat(results.get(0).reason()).isEqualTo("IOException: disk full (injected)");
        assertThat(rows(out.resolve("results.csv"))).hasSize(2);
    }

    @Test
    void aStopEndsTheSweepKeepingTheRowsDoneAndNoPartialMission() throws Exception {
        WorldSpec world = WorldFiles.load(shortWorld().resolve("short-limit.json"));
        List<SweepMission> missions = List.of(
                new SweepMission(1, world, "short-limit", Strategy.named("safety-first"), NoiseLevel.NONE, 7),
                new SweepMission(2, WorldFiles.bundled("reference-arena"), "reference-arena",
                        Strategy.named("safety-first"), NoiseLevel.NONE, 0),
                new SweepMission(3, world, "short-limit", Strategy.named("battery-first"), NoiseLevel.NONE, 7));
        Path out = Files.createDirectories(tmp.resolve("stopped"));
        Sweep sweep = new Sweep(missions, out, 1);
        AtomicBoolean firstDone = new AtomicBoolean();
        // Ctrl-C while the second mission runs: the first is done, the second is cut short at its next step
        MissionRunner runner = new MissionRunner(MissionOptions.Link.DIRECT, ScenarioPlugins.none(), (report, file) -> {
            Files.writeString(file, "{}");
            firstDone.set(true);
        }, () -> {
            if (firstDone.get()) {
                sweep.stop();
            }
            return sweep.isStopped();
        });
        List<MissionResult> results;
        try (ResultsCsv csv = new ResultsCsv(out.resolve("results.csv"));
             SweepProgress progress = SweepProgress.start(3, false, new java.io.PrintWriter(new java.io.StringWriter()))) {
            results = sweep.run(runner, csv, progress);
        }
        assertThat(results).hasSize(1);
        assertThat(rows(out.resolve("results.csv"))).containsOnlyKeys(missions.get(0).folder());
        assertThat(out.resolve(missions.get(1).folder())).doesNotExist();
        assertThat(out.resolve(missions.get(2).folder())).doesNotExist();
    }

    @Test
    void badInputExitsTwoNamingTheProblemAndWritesNothing() throws Exception {
        Path invalid = tmp.resolve("invalid.json");
        Files.writeString(invalid, "{\"name\": \"bad\", \"arena\": {\"radiusM\": -1}}");
        Path emptyDir = Files.createDirectories(tmp.resolve("empty"));
        Path full = Files.createDirectories(tmp.resolve("full"));
        Files.writeString(full.resolve("keep.txt"), "mine");
        Object[][] cases = {
                {new String[] {"--worlds", "reference-arena", "--strategies", "reckless"}, "reckless"},
                {new String[] {"--worlds", "reference-arena", "--noise", "none,loud"}, "unknown noise level loud"},
                {new String[] {"--worlds", "reference-arena", invalid.toString()}, "invalid.json: invalid world file"},
                {new String[] {"--worlds", "reference-arena", invalid.toString()}, "arena.radiusM"},
                {new String[] {"--worlds", emptyDir.toString()}, "no world file"},
                {new String[] {"--worlds", "reference-arena", "--jobs", "0"}, "--jobs must be at least 1"},
                {new String[] {"--worlds", "reference-arena", "--seeds", "1,x"}, "--seeds"},
                {new String[] {"--worlds", "reference-arena", "--link", "pigeon"}, "--link must be jdbc or direct"},
                {new String[] {"--worlds", "no-such-world"}, "no-such-world: no such file"},
        };
        for (Object[] c : cases) {
            Path out = tmp.resolve("out-" + Math.abs(c[1].hashCode()));
            String[] args = concat((String[]) c[0], "--out", out.toString());
            err.getBuffer().setLength(0);
            assertThat(run(args)).as(String.join(" ", args)).isEqualTo(2);
            assertThat(err.toString()).as(String.join(" ", args)).contains((String) c[1]);
            assertThat(out).doesNotExist();
        }
        err.getBuffer().setLength(0);
        assertThat(run("sweep", "--worlds", "reference-arena", "--out", full.toString())).isEqualTo(2);
        assertThat(err.toString()).isEqualTo("--out " + full
                + " exists and is not empty: give --force to write into it anyway, or another folder\n");
        assertThat(err.toString()).contains("exists and is not empty", "--force");
        try (var files = Files.list(full)) {
            assertThat(files.map(p -> p.getFileName().toString()).toList()).containsExactly("keep.txt");
        }
    }

    @Test
    void helpNamesEveryFileOfAMissionsFolder() throws Exception {
        Path folder = tmp.resolve("one");
        assertThat(run("sweep", "--worlds", shortWorld().toString(), "--link", "direct", "--out", folder.toString()))
                .as(err.toString()).isEqualTo(1);
        List<String> files;
        try (var dirs = Files.list(folder)) {
            Path mission = dirs.filter(Files::isDirectory).findFirst().orElseThrow();
            try (var in = Files.list(mission)) {
                files = in.map(p -> p.getFileName().toString()).sorted().toList();
            }
        }
        assertThat(files).containsExactly("replay.html", "report.json", "trace.jsonl", "trajectory.svg", "world.json");
        out.getBuffer().setLength(0);
        assertThat(run("sweep", "--help")).isZero();
        assertThat(out.toString().replaceAll("\\s+", " "))
                .contains("(report.json, trace.jsonl, replay.html, trajectory.svg, world.json)");
    }

    private static String[] concat(String[] args, String... more) {
        String[] all = new String[args.length + more.length + 1];
        all[0] = "sweep";
        System.arraycopy(args, 0, all, 1, args.length);
        System.arraycopy(more, 0, all, 1 + args.length, more.length);
        return all;
    }

    /** results.csv's rows by mission folder. */
    private static Map<String, CSVRecord> rows(Path csv) throws IOException {
        try (Reader in = Files.newBufferedReader(csv, StandardCharsets.UTF_8)) {
            return CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in).getRecords().stream()
                    .collect(Collectors.toMap(r -> r.get("mission"), r -> r, (a, b) -> a, TreeMap::new));
        }
    }

    private static Map<String, Map<String, String>> withoutWallTime(Map<String, CSVRecord> rows) {
        Map<String, Map<String, String>> result = new TreeMap<>();
        rows.forEach((k, r) -> {
            Map<String, String> m = new TreeMap<>(r.toMap());
            m.remove("wallTimeS");
            result.put(k, m);
        });
        return result;
    }

}
