package org.proactiverobotics.app;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.SQLException;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Iterator;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.proactiverobotics.app.deploy.DatabaseProblem;
import org.proactiverobotics.app.deploy.DatabaseWait;
import org.proactiverobotics.app.deploy.DbOptions;
import org.proactiverobotics.app.deploy.OutputDirectory;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.RobotReport;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.app.mission.Progress;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code run}: the headless mission in one process (docs/command-line.md): engine, robot controller
 * and simulator in lockstep through a database, embedded H2 unless {@code --db} names another.
 * Writes report.json, trace.jsonl, replay.html and trajectory.svg. Input is checked before anything is
 * written: a bad world or option leaves no output directory.
 */
@Command(name = "run",
        mixinStandardHelpOptions = true,
        description = {"Runs a headless mission: the proactive engine drives the simulated robot through a shared database.",
                "Writes report.json, trace.jsonl, replay.html and trajectory.svg to the output directory (and run.mcap with --mcap).",
                "Exit codes: 0 mission accomplished, 1 mission failed, 2 bad input, 3 infrastructure failure."})
public final class RunCommand implements Callable<Integer> {

    @Option(names = "--world", paramLabel = "FILE|NAME", completionCandidates = WorldArgument.BundledNames.class,
            description = "The world: a JSON file, or the name of a bundled world (${COMPLETION-CANDIDATES}; see the"
                    + " worlds command). Default: " + WorldFiles.DEFAULT_WORLD + ".")
    private String world;

    @Option(names = "--out", paramLabel = "DIR",
            description = "Output directory; must not exist or be empty. Default: runs/<world-name>-<yyyyMMdd-HHmmss>/.")
    private Path out;

    @Option(names = "--force", description = "Write into --out even if it is not empty (files of the same names are replaced).")
    private boolean force;

    @Option(names = "--db", paramLabel = "JDBC_URL",
            description = "The shared database, e.g. jdbc:mariadb://127.0.0.1:3306/proactive. Default: embedded H2.")
    private String db;

    @Option(names = "--db-user", paramLabel = "U", description = "Database user.")
    private String dbUser;

    @Option(names = "--db-password", paramLabel = "P", defaultValue = "${env:" + DbOptions.PASSWORD_VARIABLE + "}",
            description = "Database password. Default: the environment variable " + DbOptions.PASSWORD_VARIABLE + ".")
    private String dbPassword;

    @Option(names = "--wait-s", paramLabel = "S", defaultValue = "60",
            description = "With --db: how long to wait for a database server that is not up yet (connection refused,"
                    + " unknown host) before giving up (exit 3); access denied and an unknown database fail at once."
                    + " Default: ${DEFAULT-VALUE} s.")
    private int waitS;

    @Mixin
    private ScenarioOptions scenarios;

    @Option(names = "--link", paramLabel = "LAYER", defaultValue = "jdbc",
            description = "How the engine and the robot talk: jdbc (the shared database) or direct (in-process memory, "
                    + "no database: what the middleware costs is the difference). Default: ${DEFAULT-VALUE}.")
    private String link;

    @Option(names = "--robot-id", paramLabel = "N", defaultValue = "1",
            description = "The robot's id in the shared tables; a run starts a clean mission for it (its earlier rows"
                    + " in --db are deleted). Default: ${DEFAULT-VALUE}.")
    private int robotId;

    @Mixin
    private NoiseOption noise;

    @Option(names = "--mcap", description = "Also write run.mcap: the run as an MCAP file for Foxglove (docs/foxglove.md).")
    private boolean mcap;

    @Option(names = "--threads", paramLabel = "N", defaultValue = "1",
            description = "With a world of several robots: how many threads iterate the robots' engines (the run is the"
                    + " same, bit for bit, whatever N). Default: ${DEFAULT-VALUE}.")
    private int threads;

    @Option(names = "--quiet", description = "No live progress line.")
    private boolean quiet;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        WorldSpec spec = WorldArgument.load(world, err);
        if (spec == null) {
            return Main.EXIT_BAD_INPUT;
        }
        if (robotId < 0) {
            err.println("--robot-id must be >= 0: " + robotId);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        ScenarioOptions.Choice choice;
        try {
            choice = scenarios.load(spec.hasSeveralRobots());
        } catch (IllegalArgumentException e) { // a plug-in or strategy that cannot be used
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        if (noise.problem() != null) {
            err.println(noise.problem());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        NoiseLevel noiseLevel = noise.level();
        if (threads < 1) {
            err.println("--threads must be >= 1: " + threads);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        if (waitS < 0) {
            err.println("--wait-s must be >= 0: " + waitS);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        if (db != null && !DbOptions.driverAccepts(db)) {
            err.println("--db must be a JDBC URL this program has a driver for (jdbc:h2:..., jdbc:mariadb://...,"
                    + " jdbc:mysql://...): " + DbOptions.redacted(db));
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        MissionOptions.Link layer = MissionOptions.Link.of(link);
        if (layer == null || (layer == MissionOptions.Link.DIRECT && db != null)) {
            err.println(layer == null ? "--link must be jdbc or direct: " + link
                    : "--link direct uses no database: drop --db");
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        Path outDir = out != null ? out : Path.of("runs", spec.name() + "-"
                + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")));
        String url = db != null ? db : Databases.embeddedH2Url("proactive_run_" + System.nanoTime());
        MissionOptions options = new MissionOptions(spec, url, db != null ? dbUser : "sa", db != null ? dbPassword : "",
                Strategy.SAFETY_FIRST, robotId).withLink(layer).withScenarios(choice.plugins(), choice.strategy())
                .withNoise(noiseLevel);
        String refusal = OutputDirectory.refusal(outDir, force);
        if (refusal != null) {
            err.println(refusal);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        OutputDirectory output;
        try {
            output = OutputDirectory.create(outDir);
        } catch (IOException e) {
            err.println("cannot create the output directory " + outDir + " (" + OutputDirectory.reason(e)
                    + "): give --out a folder you can write to");
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        if (db != null) {
            try {
                DatabaseWait.await(DbOptions.of(db, dbUser, dbPassword, waitS), null, () -> false);
            } catch (DatabaseWait.Unreachable e) {
                output.removeIfEmpty();
                err.println(e.getMessage());
                err.flush();
                return Main.EXIT_INFRASTRUCTURE;
            }
        }
        boolean live = !quiet && System.console() != null;
        if (choice.unlistedWarning() != null) {
            err.println(choice.unlistedWarning());
            err.flush();
        }
        stdout.printf(Locale.ROOT, "Mission %s on %s, strategy %s%s%s%n", spec.name(),
                layer == MissionOptions.Link.DIRECT ? "the direct in-process link" : db != null ? DbOptions.redacted(db) : "embedded H2",
                choice.strategy().name(), choice.plugins().scenarios().isEmpty() ? ""
                        : ", plug-in scenarios " + String.join(", ", choice.plugins().scenarios().keySet()),
                noiseLevel == NoiseLevel.NONE ? "" : ", " + noiseLevel.label() + " sensor noise");
        stdout.flush();
        MissionReport report;
        try {
            Mission mission = new Mission(options).mcap(mcap).threads(threads);
            if (live) {
                var progress = new ProgressPrinter(System.out, spec);
                mission.onStep(progress::update);
                report = mission.run(outDir);
                progress.finish();
            } else {
                report = mission.run(outDir);
            }
            writeReport(report, outDir.resolve("report.json"));
        } catch (SQLException e) {
            output.removeIfEmpty();
            err.println(DatabaseProblem.of(e, url, null).message());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        } catch (IOException e) {
            err.println("cannot write the output in " + outDir + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        } catch (RuntimeException e) { // the database failing mid-mission (engine state, tables)
            output.removeIfEmpty();
            err.println("mission aborted: " + (hasSqlCause(e) ? DatabaseProblem.of(e, url, null).message() : e.getMessage()));
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        if (report.hasRobots()) {
            for (RobotReport r : report.robots()) {
                stdout.printf(Locale.ROOT, "  robot %d: %s, checkpoints %d/%d, %.1f m, %s (%d with robots), battery min %.1f %%%n",
                        r.id(), r.outcome(), r.checkpointsReached(), r.checkpointsTotal(), r.distanceM(),
                        Plural.of(r.collisions(), "collision"), r.robotCollisions(), r.minBattery());
            }
        }
        stdout.printf(Locale.ROOT, "%s: %s, checkpoints %d/%d, %.1f s simulated in %.2f s (%.0fx real time)%n"
                        + "  %.1f m travelled, %s, battery min %.1f %%, %s%n",
                report.world(), report.outcome(), report.checkpointsReached(), report.checkpointsTotal(),
                report.simTimeS(), report.wallTimeS(), report.realTimeFactor(), report.distanceM(),
                Plural.of(report.collisions(), "collision"), report.minBattery(), Plural.of(report.recharges(), "recharge"));
        stdout.println("Report: " + outDir.resolve("report.json"));
        stdout.flush();
        return report.success() ? 0 : Main.EXIT_MISSION_FAILED;
    }

    private static boolean hasSqlCause(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause() == t ? null : t.getCause()) {
            if (t instanceof SQLException) {
                return true;
            }
        }
        return false;
    }

    /** Writes report.json as run writes it (sweep writes each mission's the same way). */
    static void writeReport(MissionReport report, Path file) throws IOException {
        Gson gson = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();
        Files.writeString(file, gson.toJson(report) + "\n", StandardCharsets.UTF_8);
    }

    /** The strategy names, for --help. */
    static final class StrategyNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return Strategy.names().iterator();
        }
    }

    /** Adapts the mission's per-step hook to the live progress line. */
    private static final class ProgressPrinter {
        private final Progress line;
        private final long startNs = System.nanoTime();
        private final int total;

        ProgressPrinter(PrintStream out, WorldSpec world) {
            this.line = new Progress(out);
            this.total = world.robots().stream().mapToInt(r -> r.checkpoints().size()).sum();
        }

        /** Every robot's checkpoints together, the lowest battery. */
        void update(Simulation sim) {
            int reached = 0;
            double battery = Double.POSITIVE_INFINITY;
            for (int i = 0; i < sim.robotCount(); i++) {
                GroundTruth truth = sim.groundTruth(i);
                reached += truth.checkpointsReached();
                battery = Math.min(battery, truth.batteryPct());
            }
            double wallS = (System.nanoTime() - startNs) / 1e9;
            line.update(sim.simTimeS(), reached, total, battery, sim.simTimeS() / Math.max(wallS, 1e-9));
        }

        void finish() {
            line.finish();
        }
    }
}
