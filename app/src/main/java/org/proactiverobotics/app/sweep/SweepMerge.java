package org.proactiverobotics.app.sweep;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.IntFunction;
import java.util.stream.Collectors;
import org.apache.commons.csv.CSVParser;
import org.proactiverobotics.app.Plural;
import org.apache.commons.csv.CSVRecord;

/**
 * Joins the folders of a sharded sweep's slices ({@code sweep --shard I/N}) into one results.csv
 * and summary.html, as one unsharded sweep would have written them (rows in the missions' order).
 * It refuses, changing nothing, shards of different sweeps or cut into a different number of
 * slices, a slice given twice or missing, and a mission with no row or with two.
 */
public final class SweepMerge {

    /**
     * What was merged.
     *
     * @param missions          rows in the merged results.csv
     * @param accomplished      of them, missions accomplished
     * @param shards            slices joined
     * @param missionsWallTimeS the missions' wall times added up, seconds
     */
    public record Merged(int missions, int accomplished, int shards, double missionsWallTimeS) {
    }

    /** The shards cannot be merged: the message names the folders and what is wrong. */
    public static final class Refused extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Refused(String message) {
            super(message);
        }
    }

    private SweepMerge() {
    }

    /** One shard's folder, its sweep.json and its rows by mission number. */
    private record ShardDir(Path dir, SweepManifest manifest, Map<Integer, CSVRecord> rows) {
    }

    /**
     * Checks that the shards make one whole sweep, then writes the merged results.csv and summary.html.
     *
     * @param dirs  the shards' folders (each with sweep.json and results.csv), in any order
     * @param out   where results.csv and summary.html go (created if missing; must not be a shard's folder)
     * @param force whether a results.csv or summary.html already in {@code out} may be replaced
     * @return what was merged
     * @throws Refused when the shards do not make one whole sweep (nothing is written)
     * @throws IOException when a file cannot be read or written
     */
    public static Merged merge(List<Path> dirs, Path out, boolean force) throws IOException {
        if (dirs.isEmpty()) {
            throw new Refused("give the folders of every shard of the sweep");
        }
        List<ShardDir> shards = new ArrayList<>();
        for (Path dir : dirs) {
            shards.add(read(dir));
        }
        checkOneSweep(shards);
        Map<Integer, ShardDir> bySlice = checkEverySliceOnce(shards);
        TreeMap<Integer, CSVRecord> rows = new TreeMap<>();
        bySlice.values().forEach(s -> rows.putAll(s.rows()));
        Shard cut = shards.get(0).manifest().slice();
        // mission k is in the folder of slice (k - 1) mod N: read() refused a row anywhere else
        IntFunction<ShardDir> folderOf = k -> bySlice.get((k - 1) % cut.count());
        int total = shards.get(0).manifest().missions();
        List<Integer> missing = new ArrayList<>();
        for (int k = 1; k <= total; k++) {
            if (!rows.containsKey(k)) {
                missing.add(k);
            }
        }
        if (!missing.isEmpty()) {
            String where = missing.stream().map(k -> folderOf.apply(k).dir().toString()).distinct()
                    .collect(Collectors.joining(", "));
            throw new Refused(missing.size() + " of " + total + (missing.size() == 1 ? " missions has no row (mission "
                    : " missions have no row (missions ") + list(missing)
                    + ") in " + where + ": was that shard stopped or did it fail? run it again, then merge");
        }
        for (ShardDir s : shards) {
            if (s.dir().toAbsolutePath().normalize().equals(out.toAbsolutePath().normalize())) {
                throw new Refused("--out " + out + " is the shard " + s.dir() + ": merge into another folder (e.g. the shards' parent)");
            }
        }
        Path csv = out.resolve("results.csv");
        Path page = out.resolve("summary.html");
        if ((Files.exists(csv) || Files.exists(page)) && !force) {
            throw new Refused((Files.exists(csv) ? csv : page) + " exists (give --force to replace it)");
        }
        int accomplished = 0;
        double wallS = 0;
        List<SummaryHtml.Row> summary = new ArrayList<>(rows.size());
        for (Map.Entry<Integer, CSVRecord> e : rows.entrySet()) {
            SummaryHtml.Row row = summaryRow(e.getValue(), folderOf.apply(e.getKey()).dir(), out);
            summary.add(row);
            accomplished += row.success() ? 1 : 0;
            wallS += row.wallTimeS();
        }
        String lead = String.format(Locale.ROOT,
                "%d of %s accomplished; merged from %s (%.1f s of missions' wall time in all)",
                accomplished, Plural.of(rows.size(), "mission"), Plural.of(bySlice.size(), "shard"), wallS);
        Files.createDirectories(out);
        // both files whole or not at all: written beside, then moved in, results.csv last
        String part = "." + ProcessHandle.current().pid() + ".part"; // created as any file is (the umask's permissions)
        Path partialCsv = out.resolve("results.csv" + part);
        Path partialPage = out.resolve("summary.html" + part);
        Path robots = out.resolve(RobotsCsv.FILE_NAME);
        Path partialRobots = out.resolve(RobotsCsv.FILE_NAME + part);
        try {
            if (mergeRobots(bySlice.values(), partialRobots)) { // shards of worlds with several robots
                Files.move(partialRobots, robots, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            }
            try (ResultsCsv merged = new ResultsCsv(partialCsv)) {
                for (CSVRecord r : rows.values()) {
                    merged.appendValues(r.toList());
                }
            }
            SummaryHtml.writeRows(summary, lead, partialPage);
            Files.move(partialPage, page, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            Files.move(partialCsv, csv, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(partialCsv);
            Files.deleteIfExists(partialPage);
            Files.deleteIfExists(partialRobots);
        }
        return new Merged(rows.size(), accomplished, bySlice.size(), wallS);
    }

    /**
     * The shards' robots.csv in one, in the missions' order (each mission's robots in the world's order).
     *
     * @return false when no shard has one (a sweep of one-robot worlds): nothing written
     */
    private static boolean mergeRobots(Collection<ShardDir> shards, Path file) throws IOException {
        TreeMap<Integer, List<List<String>>> byMission = new TreeMap<>();
        boolean any = false;
        for (ShardDir s : shards) {
            Path csv = s.dir().resolve(RobotsCsv.FILE_NAME);
            if (!Files.exists(csv)) {
                continue;
            }
            any = true;
            try (Reader in = Files.newBufferedReader(csv, StandardCharsets.UTF_8);
                 CSVParser p = ResultsCsv.FORMAT.builder().setHeader().setSkipHeaderRecord(true)
                         .get().parse(in)) {
                for (CSVRecord r : p) {
                    byMission.computeIfAbsent(missionNumber(csv, r.get("mission")), k -> new ArrayList<>()).add(r.toList());
                }
            }
        }
        if (!any) {
            return false;
        }
        try (RobotsCsv merged = new RobotsCsv(file)) {
            for (List<List<String>> rows : byMission.values()) {
                rows.forEach(merged::appendValues);
            }
        }
        return true;
    }

    /** A row of results.csv as summary.html shows it, its link relative to out; a value that is not a number is refused. */
    private static SummaryHtml.Row summaryRow(CSVRecord r, Path shard, Path out) {
        try {
            return new SummaryHtml.Row(missionNumber(shard.resolve("results.csv"), r.get("mission")), r.get("world"),
                    r.get("strategy"), r.get("noise"), Long.parseLong(r.get("seed")), r.get("outcome"),
                    Boolean.parseBoolean(r.get("success")), r.get("checkpointsReached") + "/" + r.get("checkpointsTotal"),
                    Double.parseDouble(r.get("simTimeS")), Double.parseDouble(r.get("wallTimeS")),
                    Double.parseDouble(r.get("distanceM")), Integer.parseInt(r.get("collisions")),
                    Double.parseDouble(r.get("minBattery")), Integer.parseInt(r.get("recharges")), r.get("reason"),
                    SummaryHtml.link(out, shard.resolve(r.get("mission"))));
        } catch (NumberFormatException e) {
            throw new Refused(shard.resolve("results.csv") + ": mission " + r.get("mission") + " has a value that is not a"
                    + " number (" + e.getMessage() + ")");
        }
    }

    private static ShardDir read(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            throw new Refused(dir + " is not a folder (give the folders sweep --shard wrote)");
        }
        SweepManifest manifest;
        try {
            manifest = SweepManifest.read(dir);
        } catch (NoSuchFileException e) {
            throw new Refused(dir + " has no " + SweepManifest.FILE + ": not a sweep's folder");
        } catch (IllegalArgumentException e) {
            throw new Refused(e.getMessage());
        }
        Path csv = dir.resolve("results.csv");
        if (!Files.isRegularFile(csv)) {
            throw new Refused(dir + " has no results.csv: did its sweep start?");
        }
        Shard slice = manifest.slice();
        Map<Integer, CSVRecord> rows = new TreeMap<>();
        try (Reader in = Files.newBufferedReader(csv, StandardCharsets.UTF_8);
             CSVParser parser = ResultsCsv.FORMAT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in)) {
            if (!parser.getHeaderNames().equals(ResultsCsv.COLUMNS)) {
                throw new Refused(csv + ": its columns are not results.csv's " + ResultsCsv.COLUMNS);
            }
            for (CSVRecord r : parser) {
                if (!r.isConsistent()) {
                    throw new Refused(csv + ": line " + parser.getCurrentLineNumber() + " has " + r.size() + " values, not "
                            + ResultsCsv.COLUMNS.size() + " (a row cut short?)");
                }
                int k = missionNumber(csv, r.get("mission"));
                if (k > manifest.missions() || !slice.contains(k)) {
                    throw new Refused(csv + ": mission " + r.get("mission") + " is not one of shard " + slice + "'s");
                }
                if (rows.put(k, r) != null) {
                    throw new Refused(csv + ": mission " + r.get("mission") + " has two rows");
                }
            }
        }
        return new ShardDir(dir, manifest, rows);
    }

    private static int missionNumber(Path csv, String folder) {
        int dash = folder.indexOf('-');
        try {
            int k = Integer.parseInt(dash < 0 ? folder : folder.substring(0, dash));
            if (k >= 1) {
                return k;
            }
        } catch (NumberFormatException e) {
            // named below
        }
        throw new Refused(csv + ": the mission column " + folder + " does not start with the mission's number");
    }

    private static void checkOneSweep(List<ShardDir> shards) {
        ShardDir first = shards.get(0);
        for (ShardDir s : shards) {
            if (!s.manifest().definition().equals(first.manifest().definition())) {
                throw new Refused("shards of different sweeps (" + difference(first.manifest(), s.manifest()) + "): "
                        + first.dir() + " (definition " + first.manifest().definition().substring(0, 12) + ") and "
                        + s.dir() + " (definition " + s.manifest().definition().substring(0, 12) + ")");
            }
            if (s.manifest().shards() != first.manifest().shards()) {
                throw new Refused("shards cut differently: " + first.dir() + " is " + first.manifest().slice() + " and "
                        + s.dir() + " is " + s.manifest().slice() + " (merge the slices of one cut)");
            }
        }
    }

    /** What two sweeps' manifests say differs, as far as they say it. */
    private static String difference(SweepManifest a, SweepManifest b) {
        if (!a.link().equals(b.link())) {
            return "link " + a.link() + " against " + b.link();
        }
        if (!a.version().equals(b.version())) {
            return "program " + a.version() + " against " + b.version();
        }
        if (a.missions() != b.missions()) {
            return Plural.of(a.missions(), "mission") + " against " + b.missions();
        }
        return "the same number of missions, but other worlds, strategies, noise levels, seeds or plug-ins";
    }

    private static Map<Integer, ShardDir> checkEverySliceOnce(List<ShardDir> shards) {
        Map<Integer, ShardDir> bySlice = new TreeMap<>();
        for (ShardDir s : shards) {
            ShardDir before = bySlice.put(s.manifest().shard(), s);
            if (before != null) {
                throw new Refused("shard " + s.manifest().slice() + " given twice: " + before.dir() + " and " + s.dir());
            }
        }
        int count = shards.get(0).manifest().shards();
        List<String> missing = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            if (!bySlice.containsKey(i)) {
                missing.add(i + "/" + count);
            }
        }
        if (!missing.isEmpty()) {
            throw new Refused((missing.size() == 1 ? "shard " : "shards ") + String.join(", ", missing)
                    + " missing: give the folders of all " + count + " shards");
        }
        return bySlice;
    }

    private static String list(List<Integer> numbers) {
        List<String> shown = numbers.stream().sorted(Comparator.naturalOrder()).limit(8).map(String::valueOf).toList();
        return String.join(", ", shown) + (numbers.size() > shown.size() ? " and " + (numbers.size() - shown.size()) + " more" : "");
    }
}
