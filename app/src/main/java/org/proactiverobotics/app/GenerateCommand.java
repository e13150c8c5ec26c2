package org.proactiverobotics.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.proactiverobotics.app.deploy.OutputDirectory;
import org.proactiverobotics.app.generate.Solvability;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code generate}: N world files of a kind drawn from a seed, each valid and checked solvable by a
 * grid planner before it is written (a folder to give {@code sweep --worlds}).
 */
@Command(name = "generate",
        mixinStandardHelpOptions = true,
        description = {"Writes N world files of a kind, drawn from a seed, each valid and checked solvable by a grid planner"
                + " (every checkpoint reachable in order, the battery enough with recharges) before it is written.",
                "Exit codes: 0 written, 2 bad input (nothing written), 3 the files could not be written."})
public final class GenerateCommand implements Callable<Integer> {

    @Option(names = "--kind", paramLabel = "KIND", required = true,
            description = "cluttered, traps, corridors, battery, pillars, rooms or maze.")
    private String kind;

    @Option(names = "--count", paramLabel = "N", required = true, description = "How many worlds (1 to 10000).")
    private int count;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1",
            description = "The seed: the same kind, seed and count give the same files. Default: ${DEFAULT-VALUE}.")
    private long seed;

    @Option(names = "--out", paramLabel = "DIR", required = true,
            description = "The folder to write <kind>-<NNN>.json into; must not exist or be empty.")
    private Path out;

    @Option(names = "--robot-radius", paramLabel = "M", defaultValue = "0.12",
            description = "The robot's radius in metres (0.05 to 0.3; corridors from 0.1, rooms from 0.07): passages,"
                    + " doors and corridors scale with it,"
                    + " and the planner checks each world on this footprint. Default: ${DEFAULT-VALUE}.")
    private double robotRadiusM;

    @Option(names = "--robots", paramLabel = "N", defaultValue = "1",
            description = "Robots in each world (1 to 8), their missions crossing each other's paths: each starts near"
                    + " another's checkpoint and has checkpoints near the others' starts; a station per two robots"
                    + " (at most 3). Default: ${DEFAULT-VALUE}.")
    private int robots;

    @Option(names = "--force", description = "Write into --out even if it is not empty.")
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
        WorldGenerator generator = new WorldGenerator(WorldGenerator.Kind.valueOf(kind.toUpperCase(Locale.ROOT)),
                robotRadiusM);
        List<WorldSpec> worlds = new ArrayList<>();
        try {
            for (int i = 1; i <= count; i++) {
                worlds.add(generator.world(seed, i, robots));
            }
        } catch (IllegalStateException e) { // nothing is written before every world is drawn
            err.println(e.getMessage() + " for a robot of radius " + robotRadiusM + " m: try another --seed or --robot-radius"
                    + (robots > 1 ? ", or fewer --robots" : ""));
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        try {
            Files.createDirectories(out);
            for (WorldSpec w : worlds) {
                Files.writeString(out.resolve(w.name() + ".json"), WorldJson.of(w), StandardCharsets.UTF_8);
            }
        } catch (IOException e) {
            err.println("cannot write the worlds in " + out + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        for (WorldSpec w : worlds) {
            if (w.hasSeveralRobots()) {
                fleetLine(stdout, w);
                continue;
            }
            Solvability plan = Solvability.of(w);
            stdout.printf(Locale.ROOT, "%s: %s, %s, planned path %.1f m, %s, maxSimTimeS %.0f%n",
                    out.resolve(w.name() + ".json"), Plural.of(w.obstacles().size(), "obstacle"),
                    Plural.of(w.checkpoints().size(), "checkpoint"), plan.lengthM(),
                    Plural.of(plan.recharges(), "recharge"), w.maxSimTimeS());
        }
        stdout.flush();
        return 0;
    }

    /** e.g. {@code out/rooms-001.json: 16 obstacles, 4 robots, 11 checkpoints, 2 stations, longest planned path 14.2 m, ...} */
    private void fleetLine(PrintWriter stdout, WorldSpec w) {
        List<Solvability> plans = Solvability.ofEachRobot(w);
        int checkpoints = w.robots().stream().mapToInt(r -> r.checkpoints().size()).sum();
        stdout.printf(Locale.ROOT, "%s: %s, %s, %s, %s, longest planned path %.1f m, %s, maxSimTimeS %.0f%n",
                out.resolve(w.name() + ".json"), Plural.of(w.obstacles().size(), "obstacle"),
                Plural.of(w.robots().size(), "robot"), Plural.of(checkpoints, "checkpoint"),
                Plural.of(w.rechargeStations().size(), "station"),
                plans.stream().mapToDouble(Solvability::lengthM).max().orElse(0),
                Plural.of(plans.stream().mapToInt(Solvability::recharges).sum(), "recharge"), w.maxSimTimeS());
    }

    private String problem() {
        if (!WorldGenerator.Kind.labels().contains(kind.toLowerCase(Locale.ROOT))) {
            return "--kind must be one of " + String.join(", ", WorldGenerator.Kind.labels()) + ": " + kind;
        }
        if (!(robotRadiusM >= WorldGenerator.MIN_RADIUS_M && robotRadiusM <= WorldGenerator.MAX_RADIUS_M)) {
            return "--robot-radius must be from 0.05 to 0.3 (metres): " + robotRadiusM;
        }
        WorldGenerator.Kind k = WorldGenerator.Kind.valueOf(kind.toUpperCase(Locale.ROOT));
        if (robotRadiusM < k.minRadiusM()) {
            return String.format(Locale.ROOT, "--robot-radius %s is too small for %s worlds: from %s m (the planner that checks"
                    + " each world keeps 5 cm round the robot, which closes passages of a few diameters of a smaller one)",
                    robotRadiusM, kind, k.minRadiusM());
        }
        if (count < 1 || count > 10_000) {
            return "--count must be from 1 to 10000: " + count;
        }
        if (robots < 1 || robots > WorldGenerator.MAX_ROBOTS) {
            return "--robots must be from 1 to " + WorldGenerator.MAX_ROBOTS + ": " + robots;
        }
        return OutputDirectory.refusal(out, force);
    }
}
