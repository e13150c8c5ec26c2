package org.proactiverobotics.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.proactiverobotics.app.deploy.OutputDirectory;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.app.mission.RobotReport;
import org.proactiverobotics.app.sweep.MissionResult;
import org.proactiverobotics.app.sweep.MissionRunner;
import org.proactiverobotics.app.sweep.ResultsCsv;
import org.proactiverobotics.app.sweep.RobotsCsv;
import org.proactiverobotics.app.sweep.Shard;
import org.proactiverobotics.app.sweep.SummaryHtml;
import org.proactiverobotics.app.sweep.Sweep;
import org.proactiverobotics.app.sweep.SweepManifest;
import org.proactiverobotics.app.sweep.SweepMission;
import org.proactiverobotics.app.sweep.SweepProgress;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.robot.StrategyException;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.WorldValidationException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code sweep}: every combination of worlds, strategies, noise levels and seeds, each as its own
 * mission (the same as {@code run}'s), in this JVM, {@code --jobs} at a time; writes results.csv
 * (a row as each mission ends), summary.html and each mission's folder. Every input is checked
 * before anything is written.
 */
@Command(name = "sweep",
        mixinStandardHelpOptions = true,
        subcommands = SweepMergeCommand.class,
        description = {"Runs every combination of worlds x strategies x noise levels x seeds as its own mission, in one JVM,"
                + " --jobs at a time, each on its own embedded database (or the direct link).",
                "Writes results.csv (one row per mission, as it ends), summary.html (a sortable table and plots) and a"
                        + " folder for each mission (report.json, trace.jsonl, replay.html, trajectory.svg, world.json), with"
                        + " --mcap also run.mcap.",
                "Exit codes: 0 every mission accomplished, 1 any was not, 2 bad input (nothing written), 3 infrastructure"
                        + " failure."})
public final class SweepCommand implements Callable<Integer> {

    // required, but checked in plan(): picocli would demand it of 'sweep merge' too
    @Option(names = "--worlds", paramLabel = "FILE|DIR|NAME", arity = "1..*", split = ",",
            description = "World files, folders of world files (*.json, e.g. what generate wrote) or bundled worlds' names."
                    + " Required.")
    private List<String> worlds = new ArrayList<>();

    @Option(names = "--strategies", paramLabel = "NAME", split = ",",
            description = "Bundled strategies: " + Strategy.SAFETY_FIRST + ", " + Strategy.DESTINATION_FIRST + ", "
                    + Strategy.BATTERY_FIRST + ". Default: " + Strategy.SAFETY_FIRST
                    + " (unless --strategy-file gives some).")
    private List<String> strategies = new ArrayList<>();

    @Option(names = "--strategy-file", paramLabel = "FILE",
            description = "A strategy file (as run's --strategy-file); repeat the option for several.")
    private List<Path> strategyFiles = new ArrayList<>();

    @Option(names = "--noise", paramLabel = "LEVEL", split = ",", defaultValue = "none",
            description = "Sensor noise levels: none, small, realistic, indoor (docs/sensors.md). Default: ${DEFAULT-VALUE}.")
    private List<String> noise;

    @Option(names = "--seeds", paramLabel = "LIST",
            description = "Noise seeds, e.g. 1,2,3 or 1..10 (each replaces the world's seed). Default: each world's own seed.")
    private String seeds;

    @Option(names = "--scenarios", paramLabel = "PATH", split = ",",
            description = "Scenario plug-ins (jars or folders of jars), loaded into every mission, as run's --scenarios."
                    + " Start order: " + ScenarioOptions.START_ORDER + ".")
    private List<Path> scenarios = new ArrayList<>();

    @Option(names = "--jobs", paramLabel = "N",
            description = "Missions at a time. Default: the number of cores (${sys:proactive.cores}).")
    private Integer jobs;

    @Option(names = "--link", paramLabel = "LAYER", defaultValue = "jdbc",
            description = "jdbc (each mission on an embedded H2 database of its own) or direct (in-process, no database)."
                    + " Default: ${DEFAULT-VALUE}.")
    private String link;

    @Option(names = "--shard", paramLabel = "I/N",
            description = "Run only slice I of N (I from 0 to N-1) of the combinations: mission k goes to slice (k-1) mod N,"
                    + " so N processes (a Slurm job array, a Kubernetes indexed Job) run every combination once;"
                    + " join their folders with 'sweep merge'. Default: 0/1, all of them.")
    private String shard;

    @Option(names = "--out", paramLabel = "DIR",
            description = "Output folder; must not exist or be empty. Default: sweeps/sweep-<yyyyMMdd-HHmmss>/.")
    private Path out;

    @Option(names = "--mcap", description = "Also write run.mcap in each mission's folder: the run for Foxglove (docs/foxglove.md).")
    private boolean mcap;

    @Option(names = "--force", description = "Write into --out even if it is not empty (files of the same names are replaced).")
    private boolean force;

    @Spec
    private CommandSpec spec;

    static {
        System.setProperty("proactive.cores", String.valueOf(Runtime.getRuntime().availableProcessors()));
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        Plan plan;
        try {
            plan = plan();
        } catch (BadInput e) {
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        Path outDir = out != null ? out : Path.of("sweeps", "sweep-"
                + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")));
        String outProblem = outProblem(outDir);
        if (outProblem != null) {
            err.println(outProblem);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        try {
            Files.createDirectories(outDir);
        } catch (IOException e) {
            err.println("cannot create the output folder " + outDir + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        return run(plan, outDir, stdout, err);
    }

    private int run(Plan plan, Path outDir, PrintWriter stdout, PrintWriter err) {
        List<SweepMission> missions = plan.missions();
        int jobsUsed = jobs != null ? jobs : Runtime.getRuntime().availableProcessors();
        stdout.printf(Locale.ROOT, "Sweep of %s (%s x %s x %s x %s) on %s, %d at a time%n",
                Plural.of(plan.all().size(), "mission"), Plural.of(plan.worldCount(), "world"),
                Plural.of(plan.strategyCount(), "strategy", "strategies"), Plural.of(plan.noiseCount(), "noise level"),
                seeds == null ? "each world's seed" : Plural.of(plan.seedCount(), "seed"),
                plan.link() == MissionOptions.Link.DIRECT ? "the direct link" : "embedded H2", jobsUsed);
        if (!plan.shard().isAll()) {
            stdout.printf(Locale.ROOT, "Shard %s: %s of the %d%n", plan.shard(), Plural.of(missions.size(), "mission"),
                    plan.all().size());
        }
        stdout.println("Output: " + outDir);
        stdout.flush();
        try {
            SweepManifest.of(plan.all(), plan.shard(), plan.link(), plan.plugins().jars(),
                    new Main.Version().getVersion()[0]).write(outDir);
        } catch (IOException e) {
            err.println("cannot write " + outDir.resolve(SweepManifest.FILE) + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        Sweep sweep = new Sweep(missions, outDir, jobsUsed);
        CountDownLatch written = new CountDownLatch(1);
        Thread onCtrlC = new Thread(() -> {
            sweep.stop();
            try {
                written.await(20, TimeUnit.SECONDS); // results.csv closed and summary.html written for the rows done
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "sweep-stop");
        Runtime.getRuntime().addShutdownHook(onCtrlC);
        long startNs = System.nanoTime();
        List<MissionResult> results;
        // worlds with several robots: a row per robot in robots.csv; a sweep of one-robot worlds writes none
        boolean fleets = missions.stream().anyMatch(m -> m.world().hasSeveralRobots());
        try (ResultsCsv csv = new ResultsCsv(outDir.resolve("results.csv"));
             RobotsCsv robotsCsv = fleets ? new RobotsCsv(outDir.resolve(RobotsCsv.FILE_NAME)) : null;
             SweepProgress progress = SweepProgress.start(missions.size(), System.console() != null, err)) {
            sweep.robots(robotsCsv);
            MissionRunner runner = new MissionRunner(plan.link(), plan.plugins(), RunCommand::writeReport, sweep::isStopped)
                    .mcap(mcap);
            results = sweep.run(runner, csv, progress);
        } catch (IOException | UncheckedIOException e) {
            err.println("cannot write the sweep's output in " + outDir + ": " + e.getMessage());
            err.flush();
            written.countDown();
            removeHook(onCtrlC);
            return Main.EXIT_INFRASTRUCTURE;
        }
        double wallS = (System.nanoTime() - startNs) / 1e9;
        long accomplished = results.stream().filter(MissionResult::success).count();
        String lead = String.format(Locale.ROOT, "%d of %s accomplished%s; %.1f s of wall time, %d at a time, %s,"
                        + " %.1f missions per minute", accomplished, Plural.of(results.size(), "mission"),
                results.size() < missions.size() ? " (stopped after " + results.size() + " of " + missions.size() + ")" : "",
                wallS, jobsUsed, plan.link() == MissionOptions.Link.DIRECT ? "direct link" : "embedded H2",
                results.size() / Math.max(wallS, 1e-9) * 60);
        if (fleets) { // a mission counts as accomplished only when all its robots are: say how the robots did
            long robots = results.stream().mapToLong(r -> Math.max(1, r.robots().size())).sum();
            long robotsDone = results.stream().mapToLong(r -> r.robots().isEmpty() ? (r.success() ? 1 : 0)
                    : r.robots().stream().filter(RobotReport::success).count()).sum();
            long robotCollisions = results.stream().flatMap(r -> r.robots().stream())
                    .mapToLong(RobotReport::robotCollisions).sum();
            lead += String.format(Locale.ROOT, "; robots: %d of %d accomplished their own mission, %s between"
                    + " robots (robots.csv)", robotsDone, robots, Plural.of(robotCollisions, "collision"));
        }
        int code;
        try {
            SummaryHtml.write(results, lead, outDir);
            stdout.println("Sweep: " + lead);
            stdout.println("Results: " + outDir.resolve("results.csv"));
            if (fleets) {
                stdout.println("Robots: " + outDir.resolve(RobotsCsv.FILE_NAME));
            }
            stdout.println("Summary: " + outDir.resolve("summary.html"));
            code = accomplished == missions.size() ? 0 : Main.EXIT_MISSION_FAILED;
        } catch (IOException e) {
            err.println("cannot write " + outDir.resolve("summary.html") + ": " + e.getMessage());
            code = Main.EXIT_INFRASTRUCTURE;
        }
        stdout.flush();
        err.flush();
        written.countDown();
        removeHook(onCtrlC);
        return code;
    }

    private static void removeHook(Thread hook) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // the JVM is shutting down (Ctrl-C): the hook is running
        }
    }

    /** Everything the sweep runs, checked. */
    private record Plan(List<SweepMission> all, Shard shard, int worldCount, int strategyCount, int noiseCount, int seedCount,
                        MissionOptions.Link link, ScenarioPlugins plugins) {

        /** @return the missions this process runs: its shard's */
        List<SweepMission> missions() {
            return all.stream().filter(m -> shard.contains(m.index())).toList();
        }
    }

    private Plan plan() {
        if (worlds.isEmpty()) {
            throw new BadInput("Missing required option: '--worlds=FILE|DIR|NAME' (see sweep --help)");
        }
        if (jobs != null && jobs < 1) {
            throw new BadInput("--jobs must be at least 1: " + jobs);
        }
        Shard slice = Shard.ALL;
        if (shard != null) {
            try {
                slice = Shard.parse(shard);
            } catch (IllegalArgumentException e) {
                throw new BadInput("--shard: " + e.getMessage());
            }
        }
        MissionOptions.Link layer = MissionOptions.Link.of(link);
        if (layer == null) {
            throw new BadInput("--link must be jdbc or direct: " + link);
        }
        Set<NoiseLevel> levelSet = new LinkedHashSet<>(); // "small,Small" is one level
        for (String n : noise) {
            try {
                levelSet.add(NoiseLevel.of(n));
            } catch (IllegalArgumentException e) {
                throw new BadInput("--noise: " + e.getMessage());
            }
        }
        List<NoiseLevel> levels = List.copyOf(levelSet);
        List<Long> seedList = seeds == null ? null : parseSeeds(seeds);
        List<WorldSpec> worldSpecs = loadWorlds();
        boolean anyFleet = worldSpecs.stream().anyMatch(WorldSpec::hasSeveralRobots); // a strategy may then name Yield
        ScenarioPlugins plugins;
        List<Strategy> strategyList = new ArrayList<>();
        try {
            plugins = ScenarioPlugins.load(scenarios, RobotEngine.builtInScenarios());
            Map<String, Integer> slots = RobotEngine.freshSlots(plugins, anyFleet);
            List<String> names = strategies.isEmpty() && strategyFiles.isEmpty() ? List.of(Strategy.SAFETY_FIRST) : strategies;
            Set<String> bundled = new LinkedHashSet<>();
            for (String name : names) {
                Strategy s = Strategy.named(name); // in any case: "safety-first,Safety-First" is one strategy
                if (bundled.add(s.name())) {
                    s.check(slots);
                    strategyList.add(s);
                }
            }
            for (Path file : strategyFiles) {
                Strategy s = Strategy.read(file);
                try {
                    s.check(slots);
                } catch (StrategyException e) {
                    throw new StrategyException("strategy file " + file + ": " + e.getMessage());
                }
                strategyList.add(s);
            }
        } catch (IllegalArgumentException e) { // PluginException, StrategyException: naming the path, file or key
            throw new BadInput(e.getMessage());
        }
        Set<String> strategyNames = new LinkedHashSet<>();
        for (Strategy s : strategyList) {
            if (!strategyNames.add(s.name())) {
                throw new BadInput("two strategies are named " + s.name() + ": results.csv could not tell them apart");
            }
        }
        List<SweepMission> missions = new ArrayList<>();
        for (WorldSpec world : worldSpecs) {
            for (Strategy strategy : strategyList) {
                for (NoiseLevel level : levels) {
                    for (long seed : seedList != null ? seedList : List.of(world.seed())) {
                        missions.add(new SweepMission(missions.size() + 1, WorldJson.withSeed(world, seed), world.name(),
                                strategy, level, seed));
                    }
                }
            }
        }
        return new Plan(missions, slice, worldSpecs.size(), strategyList.size(), levels.size(),
                seedList == null ? 1 : seedList.size(), layer, plugins);
    }

    /** Every world, files and folders expanded; every invalid one named with its problems. */
    private List<WorldSpec> loadWorlds() {
        List<String> values = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        for (String value : worlds) {
            Path dir = directory(value);
            if (dir == null) {
                values.add(value);
                continue;
            }
            try (Stream<Path> files = Files.list(dir)) {
                List<String> found = files.filter(p -> p.getFileName().toString().endsWith(".json") && Files.isRegularFile(p))
                        .map(Path::toString).sorted().toList();
                if (found.isEmpty()) {
                    problems.add(value + ": a folder with no world file (*.json)");
                }
                values.addAll(found);
            } catch (IOException e) {
                problems.add(value + ": cannot list the folder: " + e.getMessage());
            }
        }
        List<WorldSpec> loaded = new ArrayList<>();
        for (String value : values) {
            try {
                loaded.add(WorldArgument.resolve(value));
            } catch (WorldArgument.NoSuchWorld e) {
                problems.add(e.getMessage());
            } catch (WorldValidationException e) {
                problems.add(e.report());
            }
        }
        if (!problems.isEmpty()) {
            throw new BadInput(String.join(System.lineSeparator(), problems));
        }
        if (loaded.isEmpty()) {
            throw new BadInput("--worlds: no world to run");
        }
        return loaded;
    }

    private static Path directory(String value) {
        try {
            Path p = Path.of(value);
            return Files.isDirectory(p) ? p : null;
        } catch (InvalidPathException e) {
            return null;
        }
    }

    /** Parses {@code 1,2,5..8}. */
    static List<Long> parseSeeds(String list) {
        Set<Long> result = new LinkedHashSet<>();
        for (String part : list.split(",")) {
            String p = part.trim();
            try {
                int range = p.indexOf("..");
                if (range >= 0) {
                    long from = Long.parseLong(p.substring(0, range).trim());
                    long to = Long.parseLong(p.substring(range + 2).trim());
                    if (to < from || to - from >= 100_000) {
                        throw new BadInput("--seeds: the range " + p + " must go upwards and hold at most 100000 seeds");
                    }
                    for (long s = from; s <= to; s++) {
                        result.add(s);
                    }
                } else {
                    result.add(Long.parseLong(p));
                }
            } catch (NumberFormatException e) {
                throw new BadInput("--seeds: expected integers or ranges such as 1,2,5..8, got " + p);
            }
        }
        return List.copyOf(result);
    }

    private String outProblem(Path dir) {
        return OutputDirectory.refusal(dir, force);
    }

    /** Bad input: the message names the problem; the command exits 2 with nothing written. */
    private static final class BadInput extends RuntimeException {
        private static final long serialVersionUID = 1L;

        BadInput(String message) {
            super(message);
        }
    }
}
