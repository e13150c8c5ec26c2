package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.sweep.Shard;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Sharded sweeps (issue 19): {@code sweep --shard I/N} runs a disjoint slice, {@code sweep merge}
 * joins the slices into the results.csv one unsharded sweep writes (row order aside, wall times
 * aside), whatever N, and refuses with exit 2, writing nothing, anything that is not every slice of
 * one sweep exactly once. Short missions on the direct link.
 */
class SweepShardTest extends CommandLineTest {

    @TempDir
    Path tmp;

    /** Two short worlds (3 s and 4 s limits) x two noise levels: four missions that end quickly. */
    private String worlds() throws IOException {
        Path dir = Files.createDirectories(tmp.resolve("worlds"));
        for (int limit : new int[] {3, 4}) {
            WorldSpec s = Missions.shortReferenceArena("short-" + limit, limit);
            Files.writeString(dir.resolve("short-" + limit + ".json"), WorldJson.of(s));
        }
        return dir.toString();
    }

    private String[] sweep(String worlds, String noise, Path out, String... more) {
        List<String> args = new ArrayList<>(List.of("sweep", "--worlds", worlds, "--noise", noise, "--link", "direct",
                "--jobs", "1", "--out", out.toString()));
        args.addAll(List.of(more));
        return args.toArray(String[]::new);
    }

    @Test
    void everySliceOnceWhateverTheCountAndTheMergeIsTheUnshardedSweep() throws Exception {
        String worlds = worlds();
        Path whole = tmp.resolve("whole");
        assertThat(run(sweep(worlds, "none,small", whole))).as(err.toString()).isEqualTo(1); // TIME_LIMIT rows
        Map<String, Map<String, String>> expected = rowsLessWallTime(whole.resolve("results.csv"));
        assertThat(expected).hasSize(4);

        for (int n : new int[] {1, 2, 3, 5}) { // 5 slices of 4 missions: one slice is empty
            Path cut = tmp.resolve("cut-" + n);
            List<String> dirs = new ArrayList<>(List.of("sweep", "merge"));
            int missionsRun = 0;
            for (int i = n - 1; i >= 0; i--) { // in any order
                Path shard = cut.resolve("shard-" + i);
                int code = run(sweep(worlds, "none,small", shard, "--shard", i + "/" + n));
                assertThat(code).as(err.toString()).isIn(0, 1);
                Map<String, Map<String, String>> rows = rowsLessWallTime(shard.resolve("results.csv"));
                for (String mission : rows.keySet()) {
                    int k = Integer.parseInt(mission.substring(0, 4));
                    assertThat((k - 1) % n).as(mission + " in shard " + i + "/" + n).isEqualTo(i);
                    assertThat(Files.readString(shard.resolve(mission).resolve("trace.jsonl")))
                            .isEqualTo(Files.readString(whole.resolve(mission).resolve("trace.jsonl")));
                }
                missionsRun += rows.size();
                dirs.add(shard.toString());
            }
            assertThat(missionsRun).isEqualTo(4);
            out.getBuffer().setLength(0);
            assertThat(run(dirs.toArray(String[]::new))).as(err.toString()).isZero();
            assertThat(out.toString()).contains("Merged " + n + (n == 1 ? " shard" : " shards") + ": 0 of 4 missions accomplished");
            Path merged = cut.resolve("results.csv");
            assertThat(rowsLessWallTime(merged)).isEqualTo(expected);
            assertThat(missionColumn(merged)).extracting(m -> m.substring(0, 4))
                    .as("rows in the missions' order").containsExactly("0001", "0002", "0003", "0004");
            String summary = Files.readString(cut.resolve("summary.html"));
            for (String mission : expected.keySet()) {
                int k = Integer.parseInt(mission.substring(0, 4));
                assertThat(summary).contains("shard-" + ((k - 1) % n) + "/" + mission + "/replay.html");
            }
        }
    }

    @Test
    void theMergeRefusesWhatIsNotEverySliceOfOneSweepOnceAndWritesNothing() throws Exception {
        String worlds = worlds();
        Path base = tmp.resolve("base");
        for (int i = 0; i < 3; i++) {
            run(sweep(worlds, "none,small", base.resolve("s" + i), "--shard", i + "/3"));
        }
        run(sweep(worlds, "none", base.resolve("other-noise"), "--shard", "1/3"));
        run(sweep(worlds, "none,small", base.resolve("half"), "--shard", "1/2"));
        Path cutShort = copy(base.resolve("s0"), base.resolve("s0-cut-short"), csv -> csv.subList(0, csv.size() - 1));
        Path twice = copy(base.resolve("s0"), base.resolve("s0-twice"), csv -> {
            List<String> l = new ArrayList<>(csv);
            l.add(csv.get(1));
            return l;
        });
        Path noManifest = copy(base.resolve("s2"), base.resolve("s2-no-manifest"), csv -> csv);
        Files.delete(noManifest.resolve("sweep.json"));
        String s0 = base.resolve("s0").toString();
        String s1 = base.resolve("s1").toString();
        String s2 = base.resolve("s2").toString();
        Path out = tmp.resolve("merged");
        String o = out.toString();
        Object[][] cases = {
                {new String[] {"--out", o, s0, s2}, "shard 1/3 missing"},
                {new String[] {"--out", o, s0, s1, s2, s1}, "shard 1/3 given twice"},
                {new String[] {"--out", o, s0, base.resolve("other-noise").toString(), s2},
                        "shards of different sweeps (4 missions against 2)"},
                {new String[] {"--out", o, s0, base.resolve("half").toString(), s2}, "shards cut differently"},
                {new String[] {"--out", o, cutShort.toString(), s1, s2}, "1 of 4 missions has no row (mission 4)"},
                {new String[] {"--out", o, twice.toString(), s1, s2}, "has two rows"},
                {new String[] {"--out", o, s0, s1, noManifest.toString()}, "has no sweep.json"},
                {new String[] {"--out", s1, s0, s1, s2}, "is the shard"},
        };
        for (Object[] c : cases) {
            List<String> args = new ArrayList<>(List.of("sweep", "merge"));
            args.addAll(List.of((String[]) c[0]));
            err.getBuffer().setLength(0);
            assertThat(run(args.toArray(String[]::new))).as(String.join(" ", args)).isEqualTo(2);
            assertThat(err.toString()).as(String.join(" ", args)).contains((String) c[1]);
            assertThat(out).doesNotExist();
        }
        err.getBuffer().setLength(0);
        assertThat(run("sweep", "--force", "merge", "--out", out.toString(), s0, s1, s2)).as("an option before 'merge'")
                .isEqualTo(2);
        assertThat(err.toString()).contains("after 'merge'", "--force");
        assertThat(out).doesNotExist();
        Path notANumber = copy(base.resolve("s0"), base.resolve("s0-not-a-number"),
                csv -> csv.stream().map(l -> l.replace(",none,7,", ",none,seven,")).toList());
        err.getBuffer().setLength(0);
        assertThat(run("sweep", "merge", "--out", out.toString(), notANumber.toString(), s1, s2)).isEqualTo(2);
        assertThat(err.toString()).contains("not a number");
        assertThat(out).doesNotExist();
        assertThat(Files.readAllLines(base.resolve("s1/results.csv"))).hasSize(2); // the shard's own file untouched
        // and the three together merge; a second merge needs --force
        assertThat(run("sweep", "merge", "--out", out.toString(), s0, s1, s2)).as(err.toString()).isZero();
        assertThat(Files.getPosixFilePermissions(out.resolve("results.csv"))).as("readable as the shards' files are")
                .isEqualTo(Files.getPosixFilePermissions(base.resolve("s0/results.csv")));
        assertThat(Files.getPosixFilePermissions(out.resolve("summary.html")))
                .isEqualTo(Files.getPosixFilePermissions(base.resolve("s0/summary.html")));
        try (Stream<Path> left = Files.list(out)) {
            assertThat(left.map(p -> p.getFileName().toString())).containsExactlyInAnyOrder("results.csv", "summary.html");
        }
        err.getBuffer().setLength(0);
        assertThat(run("sweep", "merge", "--out", out.toString(), s0, s1, s2)).isEqualTo(2);
        assertThat(err.toString()).contains("exists (give --force");
        assertThat(run("sweep", "merge", "--out", out.toString(), "--force", s0, s1, s2)).isZero();
    }

    @Test
    void aBadShardExitsTwoAndWritesNothing() throws Exception {
        String worlds = worlds();
        for (String bad : new String[] {"3/3", "1", "a/b", "-1/2", "0/0", "2/1"}) {
            Path out = tmp.resolve("bad-" + Math.abs(bad.hashCode()));
            err.getBuffer().setLength(0);
            assertThat(run(sweep(worlds, "none", out, "--shard", bad))).as(bad).isEqualTo(2);
            assertThat(err.toString()).as(bad).contains("--shard").contains(bad);
            assertThat(out).doesNotExist();
        }
    }

    @Test
    void slicesCoverEveryMissionExactlyOnce() {
        for (int n = 1; n <= 9; n++) {
            for (int k = 1; k <= 100; k++) {
                int holders = 0;
                for (int i = 0; i < n; i++) {
                    holders += new Shard(i, n).contains(k) ? 1 : 0;
                }
                assertThat(holders).as("mission %d of %d slices", k, n).isEqualTo(1);
            }
        }
    }

    private interface Edit {
        List<String> apply(List<String> csvLines);
    }

    /** A copy of a shard's sweep.json and results.csv, its results.csv edited. */
    private static Path copy(Path shard, Path to, Edit edit) throws IOException {
        Files.createDirectories(to);
        Files.copy(shard.resolve("sweep.json"), to.resolve("sweep.json"));
        Files.write(to.resolve("results.csv"), edit.apply(Files.readAllLines(shard.resolve("results.csv"))));
        return to;
    }

    /** results.csv's mission column, in the file's order. */
    private static List<String> missionColumn(Path csv) throws IOException {
        try (Reader in = Files.newBufferedReader(csv, StandardCharsets.UTF_8);
             Stream<CSVRecord> records = CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in).stream()) {
            return records.map(r -> r.get("mission")).toList();
        }
    }

    private static Map<String, Map<String, String>> rowsLessWallTime(Path csv) throws IOException {
        Map<String, Map<String, String>> rows = new TreeMap<>();
        try (Reader in = Files.newBufferedReader(csv, StandardCharsets.UTF_8);
             Stream<CSVRecord> records = CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in).stream()) {
            records.forEach(r -> {
                Map<String, String> m = new TreeMap<>(r.toMap());
                m.remove("wallTimeS");
                rows.put(r.get("mission"), m);
            });
        }
        return rows;
    }
}
