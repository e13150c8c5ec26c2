package org.proactiverobotics.app.sweep;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
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
     * @param results the missions that finished
     * @param lead    one line on what the sweep was (counts, wall time)
     * @param outDir  the sweep's folder: summary.html goes there, links are relative to it
     * @throws IOException when it cannot be written
     */
    public static void write(List<MissionResult> results, String lead, Path outDir) throws IOException {
        JsonArray rows = new JsonArray();
        for (MissionResult r : results) {
            SweepMission m = r.mission();
            JsonObject row = new JsonObject();
            row.addProperty("index", m.index());
            row.addProperty("world", m.world().name());
            row.addProperty("worldKind", m.worldKind());
            row.addProperty("strategy", m.strategy().name());
            row.addProperty("noise", m.noise().label());
            row.addProperty("seed", m.seed());
            row.addProperty("outcome", r.outcome());
            row.addProperty("success", r.success());
            row.addProperty("checkpoints", r.checkpointsReached() + "/" + r.checkpointsTotal());
            row.addProperty("simTimeS", r.simTimeS());
            row.addProperty("wallTimeS", r.wallTimeS());
            row.addProperty("distanceM", r.distanceM());
            row.addProperty("collisions", r.collisions());
            row.addProperty("minBattery", r.minBattery());
            row.addProperty("recharges", r.recharges());
            row.addProperty("reason", r.reason());
            String link = link(outDir, m.folder());
            if (link != null) {
                row.addProperty("link", link);
            }
            rows.add(row);
        }
        JsonObject meta = new JsonObject();
        meta.addProperty("lead", lead);
        Gson gson = new Gson(); // escapes <, > and & as \\u003c...: the data cannot close the script element
        String page = template().replace("/*DATA*/[]", gson.toJson(rows)).replace("/*META*/{}", gson.toJson(meta));
        Files.writeString(outDir.resolve("summary.html"), page, StandardCharsets.UTF_8);
    }

    private static String link(Path outDir, String folder) {
        for (String file : List.of("replay.html", "trajectory.svg")) {
            if (Files.exists(outDir.resolve(folder).resolve(file))) {
                return folder + "/" + file;
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
