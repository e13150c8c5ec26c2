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
import java.util.Base64;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Function;
import org.proactiverobotics.app.generate.WorldGenerator;

/**
 * summary.html: one self-contained page (inline CSS, SVG and JavaScript, nothing fetched) that a
 * paper can quote. Success rates are k/n with a 95 % Wilson interval ({@link SuccessRate}); times,
 * distances, battery and recharges are over accomplished missions only ({@link MissionGroup});
 * tables cut the missions by strategy × noise (× world kind where the worlds are generate's, see
 * {@link WorldGenerator#kindOfName}) and by each factor alone; each chart is an inline SVG with a
 * link that saves it alone ({@link SvgBarChart}); then every mission in a sortable table whose
 * outcome links to its replay.html (else trajectory.svg). It fits a 1 280 px window: long reasons
 * wrap. {@code sweep} and {@code sweep merge} both write it through {@link #writeRows}.
 */
public final class SummaryHtml {

    private SummaryHtml() {
    }

    /**
     * One mission's row on the page.
     *
     * @param index       its number in the sweep, from 1
     * @param world       the world's name
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
    public record Row(int index, String world, String strategy, String noise, long seed, String outcome,
                      boolean success, String checkpoints, double simTimeS, double wallTimeS, double distanceM,
                      int collisions, double minBattery, int recharges, String reason, String link) {

        /** @return the world's kind when {@code generate} drew it (named {@code <kind>-<NNN>}); empty for a world named by hand */
        public Optional<String> kind() {
            return WorldGenerator.kindOfName(world);
        }
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
            rows.add(new Row(m.index(), m.world().name(), m.strategy().name(), m.noise().label(), m.seed(),
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
        Files.writeString(file, page(rows, lead), StandardCharsets.UTF_8);
    }

    /**
     * @param rows the missions' rows
     * @param lead one line on what the sweep was
     * @return the whole page
     * @throws IOException when the page's template cannot be read from the jar
     */
    static String page(List<Row> rows, String lead) throws IOException {
        boolean kinds = rows.stream().anyMatch(r -> r.kind().isPresent());
        List<MissionGroup> strategyNoise = MissionGroup.crossed(rows, List.of(Factor.STRATEGY, Factor.NOISE));
        List<String> byStrategyNoise = charts(strategyNoise, "strategy and noise", "strategy-noise");
        List<String> byKind = kinds ? charts(MissionGroup.crossed(rows, List.of(Factor.KIND, Factor.STRATEGY)),
                "world kind and strategy", "kind-strategy") : List.of();
        StringBuilder figures = new StringBuilder();
        for (int i = 0; i < byStrategyNoise.size(); i++) { // a metric by strategy and noise beside the same by world kind
            figures.append(byStrategyNoise.get(i)).append(byKind.isEmpty() ? "" : byKind.get(i));
        }
        StringBuilder tables = new StringBuilder();
        tables.append("<h2>Strategy × noise</h2>\n");
        table(tables, "strategy-noise", List.of(Factor.STRATEGY.label(), Factor.NOISE.label()), strategyNoise);
        if (kinds) {
            tables.append("<h2>Strategy × noise × world kind</h2>\n");
            table(tables, "strategy-noise-kind", List.of(Factor.STRATEGY.label(), Factor.NOISE.label(), Factor.KIND.label()),
                    MissionGroup.crossed(rows, List.of(Factor.STRATEGY, Factor.NOISE, Factor.KIND)));
        }
        tables.append("<h2>Each factor alone</h2>\n");
        List<MissionGroup> alone = new ArrayList<>();
        for (Factor f : kinds ? List.of(Factor.STRATEGY, Factor.NOISE, Factor.KIND) : List.of(Factor.STRATEGY, Factor.NOISE)) {
            for (MissionGroup g : MissionGroup.crossed(rows, List.of(f))) {
                alone.add(new MissionGroup(List.of(f.label(), g.values().get(0)), g.success(), g.simTimeS(), g.distanceM(),
                        g.minBattery(), g.recharges(), g.collisions(), g.notAccomplished()));
            }
        }
        table(tables, "by-factor", List.of("factor", "value"), alone);
        Gson gson = new Gson(); // escapes <, > and & as \\u003c...: the data cannot close the script element
        return template().replace("<!--LEAD-->", SvgBarChart.escape(lead))
                .replace("<!--KINDS-->", kinds ? KINDS_KNOWN : KINDS_UNKNOWN)
                .replace("<!--FIGURES-->", figures).replace("<!--TABLES-->", tables)
                .replace("/*DATA*/[]", gson.toJson(missions(rows)));
    }

    private static final String KINDS_KNOWN = "A world's kind is the one <code>generate</code> drew it as, read from"
            + " its name (<code>&lt;kind&gt;-&lt;NNN&gt;</code>); a world named otherwise has none (—).";
    private static final String KINDS_UNKNOWN = "No world of this sweep was drawn by <code>generate</code> (named"
            + " <code>&lt;kind&gt;-&lt;NNN&gt;</code>), so there is no table by world kind.";

    /** @return success rate, simulated time and distance of the groups, each chart in a figure with its save link */
    private static List<String> charts(List<MissionGroup> groups, String by, String slug) {
        List<String> series = new ArrayList<>(new LinkedHashSet<>(groups.stream().map(g -> g.values().get(1)).toList()));
        List<SvgBarChart.Bar> success = new ArrayList<>();
        List<SvgBarChart.Bar> time = new ArrayList<>();
        List<SvgBarChart.Bar> distance = new ArrayList<>();
        for (MissionGroup g : groups) {
            String group = g.values().get(0);
            String name = g.values().get(1);
            String who = group + ", " + name + ": ";
            SuccessRate s = g.success();
            success.add(new SvgBarChart.Bar(group, name, 100 * s.rate(), 100 * s.wilsonLow(), 100 * s.wilsonHigh(),
                    s.shownCount() + (s.missions() == 0 ? "" : "  " + s.shownPercent() + " %"),
                    who + s.shownCount() + " accomplished, " + s.shownPercent() + " % (95 % CI " + s.shownInterval() + " %)"));
            time.add(spreadBar(group, name, who, g.simTimeS(), "s"));
            distance.add(spreadBar(group, name, who, g.distanceM(), "m"));
        }
        return List.of(figure("success-by-" + slug, SvgBarChart.render("Success rate by " + by,
                "accomplished, % of missions (whiskers: 95 % Wilson interval; label: k/n)", success, 100, series)),
                figure("sim-time-by-" + slug, SvgBarChart.render("Simulated time by " + by + ", accomplished missions",
                "simulated time, s (mean; whiskers: ± 1 sd; label: n accomplished)", time, Double.NaN, series)),
                figure("distance-by-" + slug, SvgBarChart.render("Distance by " + by + ", accomplished missions",
                "distance travelled, m (mean; whiskers: ± 1 sd; label: n accomplished)", distance, Double.NaN, series)));
    }

    private static SvgBarChart.Bar spreadBar(String group, String name, String who, MissionGroup.MeanSd m, String unit) {
        boolean spread = m.count() >= 2;
        return new SvgBarChart.Bar(group, name, m.mean(), spread ? m.mean() - m.sd() : Double.NaN,
                spread ? m.mean() + m.sd() : Double.NaN, m.count() == 0 ? "— (none accomplished)" : m.shown(1) + "  n=" + m.count(),
                who + (m.count() == 0 ? "no mission accomplished" : m.shown(1) + " " + unit + " over " + m.count() + " accomplished"));
    }

    /** @return a chart inline, and a link that downloads the same SVG as a file of its own */
    private static String figure(String name, String svg) {
        String file = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg + "\n";
        String href = "data:image/svg+xml;base64," + Base64.getEncoder().encodeToString(file.getBytes(StandardCharsets.UTF_8));
        return new StringBuilder().append("<figure class=\"plot\" id=\"").append(name).append("\">").append(svg)
                .append("<figcaption><a class=\"save\" download=\"").append(name).append(".svg\" href=\"").append(href)
                .append("\">save as SVG</a> (").append(name).append(".svg)</figcaption></figure>\n").toString();
    }

    /** A table of groups: their factors' values, then the same figures for each. */
    private static void table(StringBuilder out, String id, List<String> factors, List<MissionGroup> groups) {
        out.append("<table class=\"groups\" id=\"").append(id).append("\"><thead><tr>");
        for (String f : factors) {
            out.append("<th class=\"text\" rowspan=\"2\">").append(SvgBarChart.escape(f)).append("</th>");
        }
        out.append("<th colspan=\"3\" class=\"span\">all missions</th>")
                .append("<th colspan=\"4\" class=\"span\">accomplished missions only: mean ± sd</th>")
                .append("<th class=\"span\">missions that ran</th><th class=\"text\" rowspan=\"2\">not accomplished</th></tr><tr>")
                .append("<th>accomplished k/n</th><th>success %</th><th>95 % Wilson interval, %</th>")
                .append("<th>simulated time, s</th><th>distance, m</th><th>min battery, %</th><th>recharges</th>")
                .append("<th>collisions per mission</th></tr></thead><tbody>\n");
        List<Function<MissionGroup, String>> cells = List.of(g -> g.success().shownCount(), g -> g.success().shownPercent(),
                g -> g.success().shownInterval(), g -> g.simTimeS().shown(1), g -> g.distanceM().shown(1),
                g -> g.minBattery().shown(1), g -> g.recharges().shown(2), g -> g.collisions().shown(2));
        List<String> classes = List.of("count", "percent", "interval", "time", "distance", "battery", "recharges", "collisions");
        for (MissionGroup g : groups) {
            out.append("<tr>");
            for (String v : g.values()) {
                out.append("<td class=\"text factor\">").append(SvgBarChart.escape(v)).append("</td>");
            }
            for (int i = 0; i < cells.size(); i++) {
                out.append("<td class=\"").append(classes.get(i)).append("\">").append(SvgBarChart.escape(cells.get(i).apply(g)))
                        .append("</td>");
            }
            out.append("<td class=\"text wrap\">").append(SvgBarChart.escape(g.shownNotAccomplished()))
                    .append("</td></tr>\n");
        }
        out.append("</tbody></table>\n");
    }

    /** The missions as the page's script sorts and filters them. */
    private static JsonArray missions(List<Row> rows) {
        JsonArray data = new JsonArray();
        for (Row r : rows) {
            JsonObject row = new JsonObject();
            row.addProperty("index", r.index());
            row.addProperty("world", r.world());
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
        return data;
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
