package org.proactiverobotics.app.sweep;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * summary.html: one self-contained page (inline CSS and JavaScript, no outside resource) with the
 * sweep's missions in a sortable table and bar charts of success rate, simulated time, distance,
 * minimum battery and recharges by strategy, by noise level and by world kind. Each mission's
 * outcome links to its replay.html when its folder has one, else to its trajectory.svg.
 */
public final class SummaryHtml {

    private SummaryHtml() {
    }

    /**
     * One mission's row on the page.
     *
     * @param index       its number in the sweep, from 1
     * @param world       the world's name
     * @param worldKind   the world's kind
     * @param strategy    the strategy's name
     * @param noise       the noise level
     * @param seed        the noise seed
     * @param outcome     report.json's outcome, or ERROR
     * @param success     whether it was accomplished
     * @param checkpoints reached/total
     * @param simTimeS    simulated seconds
     * @param wallTimeS   wall-clock seconds
     * @param distanceM   metres travelled
     * @param collisions  contacts
     * @param minBattery  lowest battery, percent
     * @param recharges   charging sessions
     * @param reason      why it failed; empty when accomplished
     * @param link        its replay.html or trajectory.svg relative to summary.html, or null
     */
    public record Row(int index, String world, String worldKind, String strategy, String noise, long seed, String outcome,
                      boolean success, String checkpoints, double simTimeS, double wallTimeS, double distanceM,
                      int collisions, double minBattery, int recharges, String reason, String link) {
    }

    /**
     * @param results the missions that finished
     * @param lead    one line on what the sweep was (counts, wall time)
     * @param outDir  the sweep's folder: summary.html goes there, links are relative to it
     * @throws IOException when it cannot be written
     */
    public static void write(List<MissionResult> results, String lead, Path outDir) throws IOException {
        List<Row> rows = new ArrayList<>(results.size());
        for (MissionResult r : results) {
            SweepMission m = r.mission();
            rows.add(new Row(m.index(), m.world().name(), m.worldKind(), m.strategy().name(), m.noise().label(), m.seed(),
                    r.outcome(), r.success(), r.checkpointsReached() + "/" + r.checkpointsTotal(), r.simTimeS(),
                    r.wallTimeS(), r.distanceM(), r.collisions(), r.minBattery(), r.recharges(), r.reason(),
                    link(outDir, outDir.resolve(m.folder()))));
        }
        writeRows(rows, lead, outDir.resolve("summary.html"));
    }

    /**
     * Writes the page for rows already made (a merge's, whose links point into the shards' folders).
     *
     * @param rows the missions' rows
     * @param lead one line on what the sweep was
     * @param file the page to write
     * @throws IOException when it cannot be written
     */
    public static void writeRows(List<Row> rows, String lead, Path file) throws IOException {
        JsonArray data = new JsonArray();
        for (Row r : rows) {
            JsonObject row = new JsonObject();
            row.addProperty("index", r.index());
            row.addProperty("world", r.world());
            row.addProperty("worldKind", r.worldKind());
            row.addProperty("strategy", r.strategy());
            row.addProperty("noise", r.noise());
            row.addProperty("seed", r.seed());
            row.addProperty("outcome", r.outcome());
            row.addProperty("success", r.success());
            row.addProperty("checkpoints", r.checkpoints());
            row.addProperty("simTimeS", r.simTimeS());
            row.addProperty("wallTimeS", r.wallTimeS());
            row.addProperty("distanceM", r.distanceM());
            row.addProperty("collisions", r.collisions());
            row.addProperty("minBattery", r.minBattery());
            row.addProperty("recharges", r.recharges());
            row.addProperty("reason", r.reason());
            if (r.link() != null) {
                row.addProperty("link", r.link());
            }
            data.add(row);
        }
        JsonObject meta = new JsonObject();
        meta.addProperty("lead", lead);
        Gson gson = new Gson(); // escapes <, > and & as \\u003c...: the data cannot close the script element
        String page = template().replace("/*DATA*/[]", gson.toJson(data)).replace("/*META*/{}", gson.toJson(meta));
        Files.writeString(file, page, StandardCharsets.UTF_8);
    }

    /**
     * @param outDir        where summary.html is
     * @param missionFolder a mission's folder
     * @return its replay.html (else trajectory.svg) relative to outDir, with forward slashes; null when it has neither
     */
    static String link(Path outDir, Path missionFolder) {
        for (String file : List.of("replay.html", "trajectory.svg")) {
            Path target = missionFolder.resolve(file);
            if (Files.exists(target)) {
                return outDir.toAbsolutePath().normalize().relativize(target.toAbsolutePath().normalize()).toString()
                        .replace('\\', '/');
            }
        }
        return null;
    }

    private static String template() throws IOException {
        try (InputStream in = Objects.requireNonNull(SummaryHtml.class.getResourceAsStream("summary.html"),
                "summary.html template missing from the jar")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
