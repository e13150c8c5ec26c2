package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.sweep.RobotsCsv;
import org.proactiverobotics.app.sweep.WorldJson;

/**
 * {@code sweep} with a world of several robots (docs/experiments.md): results.csv keeps a row per run (the run as a
 * whole: success only when every robot accomplished, checkpoints and collisions summed), robots.csv gets a row per
 * robot of each run as report.json's {@code robots} has it, summary.html says how the robots did; a sweep of
 * one-robot worlds writes no robots.csv.
 */
class FleetSweepTest extends CommandLineTest {

    @TempDir
    Path tmp;

    private static List<CSVRecord> rows(Path csv) throws IOException {
        try (Reader in = Files.newBufferedReader(csv);
             CSVParser p = CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in)) {
            return p.getRecords();
        }
    }

    @Test
    void aRowPerRunInResultsAndARowPerRobotInRobotsAsEachReportSaysIt() throws Exception {
        Path worlds = Files.createDirectories(tmp.resolve("worlds"));
        Files.writeString(worlds.resolve("crossing.json"), WorldJson.of(FleetMissionTest.crossing()));
        Path out = tmp.resolve("sweep");
        int code = run("sweep", "--worlds", worlds.toString(), "--noise", "none,small", "--link", "direct", "--jobs", "2",
                "--out", out.toString());
        assertThat(code).as(err.toString()).isIn(0, 1);

        List<CSVRecord> runs = rows(out.resolve("results.csv"));
        List<CSVRecord> robots = rows(out.resolve(RobotsCsv.FILE_NAME));
        assertThat(runs).hasSize(2);
        assertThat(robots).hasSize(6);
        assertThat(Files.readAllLines(out.resolve(RobotsCsv.FILE_NAME)).get(0)).isEqualTo(String.join(",", RobotsCsv.COLUMNS));
        for (CSVRecord run : runs) {
            JsonObject report = JsonParser.parseString(Files.readString(out.resolve(run.get("mission")).resolve("report.json")))
                    .getAsJsonObject();
            JsonArray each = report.getAsJsonArray("robots");
            List<CSVRecord> mine = robots.stream().filter(r -> r.get("mission").equals(run.get("mission"))).toList();
            assertThat(mine).extracting(r -> r.get("robot")).containsExactly("1", "2", "5");
            assertThat(run.get("checkpointsTotal")).isEqualTo("4");
            assertThat(run.get("success")).isEqualTo(String.valueOf(mine.stream().allMatch(r -> r.get("success").equals("true"))));
            assertThat(Integer.parseInt(run.get("checkpointsReached")))
                    .isEqualTo(mine.stream().mapToInt(r -> Integer.parseInt(r.get("checkpointsReached"))).sum());
            for (int i = 0; i < mine.size(); i++) {
                JsonObject r = each.get(i).getAsJsonObject();
                CSVRecord row = mine.get(i);
                assertThat(row.get("outcome")).isEqualTo(r.get("outcome").getAsString());
                assertThat(row.get("endSimTimeS")).isEqualTo(r.get("endSimTimeS").getAsString());
                assertThat(row.get("distanceM")).isEqualTo(r.get("distanceM").getAsString());
                assertThat(row.get("robotCollisions")).isEqualTo(r.get("robotCollisions").getAsString());
                assertThat(row.get("noise")).isEqualTo(run.get("noise"));
                assertThat(row.get("world")).isEqualTo("crossing");
            }
        }
        long accomplished = robots.stream().filter(r -> r.get("success").equals("true")).count();
        String summary = Files.readString(out.resolve("summary.html"));
        assertThat(summary).contains("robots: " + accomplished + " of 6 accomplished their own mission");
        assertThat(this.out.toString()).contains("Robots: " + out.resolve(RobotsCsv.FILE_NAME));
    }

    @Test
    void mergingShardsMergesTheirRobotsInTheMissionsOrder() throws Exception {
        Path worlds = Files.createDirectories(tmp.resolve("worlds"));
        // its first 5 s: the rows are what matters here
        Files.writeString(worlds.resolve("crossing.json"), WorldJson.of(FleetMissionTest.crossing(5.0)));
        List<String> shardRows = new ArrayList<>();
        for (int i = 0; i < 2; i++) {
            Path shard = tmp.resolve("shard-" + i);
            assertThat(run("sweep", "--worlds", worlds.toString(), "--noise", "none,small", "--link", "direct",
                    "--shard", i + "/2", "--out", shard.toString())).as(err.toString()).isIn(0, 1);
            List<String> lines = Files.readAllLines(shard.resolve(RobotsCsv.FILE_NAME));
            shardRows.addAll(lines.subList(1, lines.size()));
        }
        Path merged = tmp.resolve("merged");
        assertThat(run("sweep", "merge", tmp.resolve("shard-0").toString(), tmp.resolve("shard-1").toString(), "--out",
                merged.toString())).as(err.toString()).isIn(0, 1);
        List<String> lines = Files.readAllLines(merged.resolve(RobotsCsv.FILE_NAME));
        assertThat(lines.get(0)).isEqualTo(String.join(",", RobotsCsv.COLUMNS));
        assertThat(lines.subList(1, lines.size())).hasSize(6).containsExactlyInAnyOrderElementsOf(shardRows)
                .isSortedAccordingTo(Comparator.comparing((String l) -> l.substring(0, 4)));
    }

    @Test
    void aSweepOfOneRobotWorldsWritesNoRobotsFile() throws Exception {
        Path worlds = Files.createDirectories(tmp.resolve("worlds"));
        Files.writeString(worlds.resolve("short.json"), WorldJson.of(Missions.shortReferenceArena("short", 2.0)));
        Path out = tmp.resolve("sweep");
        assertThat(run("sweep", "--worlds", worlds.toString(), "--link", "direct", "--out", out.toString())).isIn(0, 1);
        assertThat(out.resolve("results.csv")).exists();
        assertThat(out.resolve(RobotsCsv.FILE_NAME)).doesNotExist();
        assertThat(Files.readString(out.resolve("summary.html"))).doesNotContain("robots:");
    }
}
