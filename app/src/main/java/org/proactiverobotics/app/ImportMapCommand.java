package org.proactiverobotics.app;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.proactiverobotics.app.deploy.OutputDirectory;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.app.importmap.MapImport;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.WorldValidationException;
import org.proactiverobotics.sim2d.map.MapException;
import org.proactiverobotics.sim2d.map.MapFiles;
import org.proactiverobotics.sim2d.map.OccupancyGrid;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code import-map}: a ROS map_server map or a Moving AI grid map made into a world file with a seeded
 * mission checked solvable (docs/maps.md). The world lists the map's walls as merged boxes (self-contained:
 * it runs wherever the file goes, and a sweep's copy of it is the same world), or with
 * {@code --reference-map} names the map file instead.
 */
@Command(name = "import-map",
        mixinStandardHelpOptions = true,
        description = {"Makes a map you already have into a world file: a ROS map_server map (its YAML, with a PGM or PNG"
                + " picture), a Moving AI grid map (.map), or a picture alone (a Stage bitmap: .pgm or .png, with --cell-m)."
                + " Blocked and unknown cells become merged boxes; a mission"
                + " (start, checkpoints far apart in other rooms, a station near the start) is drawn from the seed and"
                + " checked solvable on the robot's footprint, as generate checks its worlds.",
                "Exit codes: 0 written, 2 bad input or a bad map (nothing written), 3 the file could not be written."})
public final class ImportMapCommand implements Callable<Integer> {

    @Option(names = "--map", paramLabel = "FILE", required = true,
            description = "The map: a map_server YAML (.yaml, .yml), a Moving AI map (.map), or a picture alone (.pgm, .png:"
                    + " read as map_server reads one, origin 0 0, default thresholds; give --cell-m).")
    private Path map;

    @Option(names = "--out", paramLabel = "WORLD.json", required = true,
            description = "The world file to write; must not exist (unless --force).")
    private Path out;

    @Option(names = "--robot-radius", paramLabel = "M", defaultValue = "0.12",
            description = "The robot's radius in metres (0.05 to 0.3): the mission is checked on this footprint plus"
                    + " 5 cm. Default: ${DEFAULT-VALUE}.")
    private double robotRadiusM;

    @Option(names = "--checkpoints", paramLabel = "K", defaultValue = "3",
            description = "How many checkpoints (1 to 20). Default: ${DEFAULT-VALUE}.")
    private int checkpoints;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1",
            description = "The seed of the mission's draws: the same map and seed give the same world. Default: ${DEFAULT-VALUE}.")
    private long seed;

    @Option(names = "--name", paramLabel = "NAME",
            description = "The world's name (letters, digits, - and _). Default: the map file's name without its extension.")
    private String name;

    @Option(names = "--cell-m", paramLabel = "M",
            description = "Metres a cell of a Moving AI map (default 0.5) or a pixel of a picture alone (required);"
                    + " a map_server YAML gives its own resolution.")
    private Double cellM;

    @Option(names = "--reference-map",
            description = "Name the map in the world (\"map\": {\"file\": ...}, relative to the world file) instead of"
                    + " listing its boxes: a small file that follows edits to the map, but needs the map beside it.")
    private boolean referenceMap;

    @Option(names = "--force", description = "Overwrite --out if it exists.")
    private boolean force;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        String problem = problem();
        if (problem != null) {
            err.println(problem);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        long started = System.nanoTime();
        MapImport imported;
        String text;
        try {
            imported = MapImport.of(map, cellM == null ? MapFiles.DEFAULT_CELL_M : cellM, robotRadiusM, checkpoints, seed, name);
            text = referenceMap ? referencing(imported.world()) : imported.json();
        } catch (MapException e) {
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        try {
            Path parent = out.toAbsolutePath().getParent();
            Files.createDirectories(parent);
            Files.writeString(out, text, StandardCharsets.UTF_8);
        } catch (IOException e) {
            err.println("cannot write " + out + ": " + OutputDirectory.reason(e));
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        double seconds = (System.nanoTime() - started) / 1e9;
        report(stdout, imported, seconds);
        return 0;
    }

    private void report(PrintWriter stdout, MapImport imported, double seconds) {
        OccupancyGrid g = imported.grid();
        WorldSpec w = imported.world();
        stdout.printf(Locale.ROOT, "%s: %.1f x %.1f m (%d x %d cells of %s m), free floor %.1f m², %s%n", map, g.widthM(),
                g.heightM(), g.columns(), g.rows(), g.cellM(), imported.freeAreaM2(), Plural.of(w.obstacles().size(), "box", "boxes"));
        for (String warning : imported.warnings()) {
            stdout.println("warning: " + warning);
        }
        WorldSpec.Robot r = w.robot();
        stdout.printf(Locale.ROOT, "mission: start (%s, %s), station (%s, %s), %s (the floor falls into %s); planned path"
                        + " %.1f m, %s, maxSimTimeS %.0f%n", r.x(), r.y(), w.rechargeStation().x(), w.rechargeStation().y(),
                Plural.of(w.checkpoints().size(), "checkpoint"), Plural.of(imported.rooms(), "room"),
                imported.plan().lengthM(), Plural.of(imported.plan().recharges(), "recharge"), w.maxSimTimeS());
        stdout.printf(Locale.ROOT, "wrote %s (%s) in %.1f s%n", out, referenceMap ? "names the map" : "boxes inline", seconds);
        stdout.flush();
    }

    /**
     * The world naming the map instead of listing its boxes: no arena (the map's extent) and no obstacles;
     * read back here to be sure it is the same world.
     */
    private String referencing(WorldSpec world) {
        JsonObject root = JsonParser.parseString(WorldJson.of(world.withObstacles(List.of()))).getAsJsonObject();
        root.remove("arena");
        root.remove("obstacles");
        Path dir = out.toAbsolutePath().getParent();
        Path relative = dir.relativize(map.toAbsolutePath());
        JsonObject m = new JsonObject();
        m.addProperty("file", relative.toString().replace('\\', '/'));
        if (MapFiles.takesCellSize(map) && cellM != null) {
            m.addProperty("cellM", cellM);
        }
        root.add("map", m);
        String text = new GsonBuilder().setPrettyPrinting().create().toJson(root) + "\n";
        try {
            WorldSpec back = WorldFiles.parse(text, out.toString(), dir);
            if (!back.equals(world)) {
                throw new IllegalStateException("the world naming " + relative + " reads back other than its boxes");
            }
        } catch (WorldValidationException e) {
            throw new IllegalStateException("the world naming " + relative + " fails its own checks: " + e.problems(), e);
        }
        return text;
    }

    private String problem() {
        if (!(robotRadiusM >= WorldGenerator.MIN_RADIUS_M && robotRadiusM <= WorldGenerator.MAX_RADIUS_M)) {
            return "--robot-radius must be from 0.05 to 0.3 (metres): " + robotRadiusM;
        }
        if (checkpoints < 1 || checkpoints > 20) {
            return "--checkpoints must be from 1 to 20: " + checkpoints;
        }
        if (name != null && !name.matches("[A-Za-z0-9_-]+")) {
            return "--name must be letters, digits, '-' or '_': " + name;
        }
        if (!MapFiles.takesCellSize(map) && !MapFiles.isMapServer(map)) {
            return map + ": not a map this reads: give a ROS map_server YAML (.yaml), a Moving AI map (.map), or a picture"
                    + " (.pgm, .png) with --cell-m";
        }
        if (cellM != null && !(cellM > 0 && cellM <= 100)) {
            return "--cell-m must be above 0 and at most 100 (metres a cell or a pixel): " + cellM;
        }
        if (cellM != null && !MapFiles.takesCellSize(map)) {
            return "--cell-m is for Moving AI maps (.map) and pictures alone (.pgm, .png); " + map + " gives its own resolution";
        }
        if (cellM == null && MapFiles.isPicture(map)) {
            return map + ": a picture alone has no scale: give --cell-m (metres a pixel; 0.05 for most ROS maps), or its"
                    + " map_server YAML";
        }
        if (Files.isDirectory(out)) {
            return "--out " + out + " is a folder: give the world file's name, such as " + out.resolve("world.json");
        }
        if (Files.exists(out) && !force) {
            return "--out " + out + " exists: give --force to overwrite it, or another name";
        }
        if (!out.getFileName().toString().endsWith(".json")) {
            return "--out " + out + ": a world file's name ends in .json";
        }
        return null;
    }
}
