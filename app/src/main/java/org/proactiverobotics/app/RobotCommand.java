package org.proactiverobotics.app;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.proactiverobotics.app.deploy.DatabaseWait;
import org.proactiverobotics.app.deploy.DbOptions;
import org.proactiverobotics.app.deploy.FleetProcess;
import org.proactiverobotics.app.deploy.OutputDirectory;
import org.proactiverobotics.app.deploy.ProcessOptions;
import org.proactiverobotics.app.deploy.RobotProcess;
import org.proactiverobotics.app.deploy.ServiceLogging;
import org.proactiverobotics.app.deploy.ShutdownSignal;
import org.proactiverobotics.app.deploy.StoredMission;
import org.proactiverobotics.app.foxglove.FleetLayout;
import org.proactiverobotics.app.foxglove.McapRecorder;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.RobotReport;
import org.proactiverobotics.protocol.Timing;
import org.proactiverobotics.sim2d.WorldSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robot}: the simulated robot and its {@code ProactiveController} as a process of their
 * own (the Webots controller of the paper's deployment): seeds the mission rows, runs the
 * mission with an engine process through the shared database, writes report.json and exits
 * with the codes of docs/command-line.md.
 */
@Command(name = "robot",
        mixinStandardHelpOptions = true,
        description = {"Runs the simulated robot and its controller against a shared database, driven by an `engine` process.",
                "A world with several robots: every robot's controller in this one process, each with its world id,"
                        + " served by `engine --robot-ids`.",
                "Sync timing (default): the robot acts on each step only once the engine has served it: the same run as `run`.",
                "Realtime timing: the robot steps on the wall clock, the engine iterates on its own period.",
                "Writes report.json and replay.html to the output directory (and run.mcap with --mcap).",
                "Exit codes: 0 mission accomplished, 1 mission failed or stopped, 2 bad input, 3 database not usable within --wait-s."})
public final class RobotCommand implements Callable<Integer> {

    @Option(names = "--world", paramLabel = "FILE|NAME", required = true,
            completionCandidates = WorldArgument.BundledNames.class,
            description = "The world: a JSON file, or the name of a bundled world (${COMPLETION-CANDIDATES}).")
    private String world;

    @Mixin
    private DbOptions db;

    @Mixin
    private ProcessOptions process;

    @Option(names = "--out", paramLabel = "DIR",
            description = "Output directory for report.json and replay.html; must not exist or be empty."
                    + " Default: runs/<world-name>-<yyyyMMdd-HHmmss>/.")
    private Path out;

    @Option(names = "--force", description = "Write into --out even if it is not empty (files of the same names are replaced).")
    private boolean force;

    @Option(names = "--timing", paramLabel = "MODE", defaultValue = "sync",
            description = "sync (one engine iteration per control step, deterministic) or realtime. Default: ${DEFAULT-VALUE}.")
    private String timing;

    @Option(names = "--real-time-factor", paramLabel = "F", defaultValue = "1.0",
            description = "Realtime timing: simulated seconds per wall second (2 = twice as fast). Default: ${DEFAULT-VALUE}.")
    private double realTimeFactor;

    @Mixin
    private NoiseOption noise;

    @Option(names = "--mcap", description = "Also write run.mcap: the run as an MCAP file for Foxglove (docs/foxglove.md).")
    private boolean mcap;



    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        WorldSpec worldSpec = WorldArgument.load(world, err);
        if (worldSpec == null) {
            return Main.EXIT_BAD_INPUT;
        }
        String problem = problem();
        if (problem != null) {
            err.println(problem);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        Path outDir = out != null ? out : Path.of("runs", worldSpec.name() + "-"
                + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")));
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
        ServiceLogging.statusLines();
        ShutdownSignal signal = ShutdownSignal.install();
        int code = Main.EXIT_INFRASTRUCTURE; // what an unexpected exception ends with
        try {
            code = worldSpec.hasSeveralRobots() ? runWorld(worldSpec, output, signal, stdout, err)
                    : runMission(worldSpec, output, signal, stdout, err);
        } finally {
            signal.finished(code);
        }
        return code;
    }

    private int runMission(WorldSpec worldSpec, OutputDirectory output, ShutdownSignal signal, PrintWriter stdout, PrintWriter err) {
        Path outDir = output.path();
        Timing mode = Timing.of(timing.toLowerCase(Locale.ROOT)).orElseThrow(); // checked by problem()
        stdout.printf(Locale.ROOT, "Robot %d: mission %s on %s, %s timing%n", process.robotId(), worldSpec.name(), DbOptions.redacted(db.url()), mode.label());
        stdout.flush();
        MissionReport report;
        RobotProcess robot = new RobotProcess(new RobotProcess.Options(worldSpec, db, process.robotId(), mode, realTimeFactor,
                process.logEvery(), process.heartbeat(), noise.level().sensorNoise()), signal);
        McapRecorder recorder = null;
        try {
            if (mcap) {
                recorder = McapRecorder.open(outDir.resolve(McapRecorder.FILE_NAME), worldSpec);
                robot.alsoTo(recorder::record);
            }
            report = robot.run();
        } catch (IOException e) {
            err.println("cannot write " + McapRecorder.FILE_NAME + " in " + outDir + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        } catch (DatabaseWait.Unreachable | StoredMission.Mismatch e) {
            return notRun(e, recorder, output, err);
        }
        try {
            if (recorder != null) {
                recorder.close();
            }
            RunCommand.writeReport(report, outDir.resolve("report.json"));
            robot.writeReplay(outDir.resolve("replay.html"), report);
        } catch (IOException e) {
            err.println("cannot write the report in " + outDir + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        stdout.printf(Locale.ROOT, "%s: %s, checkpoints %d/%d, %.1f s simulated in %.2f s, %s, %s, "
                        + "%.1f m, %s, battery min %.1f %%, %s%n",
                report.world(), report.outcome(), report.checkpointsReached(), report.checkpointsTotal(), report.simTimeS(),
                report.wallTimeS(), Plural.of(report.controlSteps(), "step"), Plural.of(report.engineIterations(), "engine iteration"),
                report.distanceM(), Plural.of(report.collisions(), "collision"), report.minBattery(),
                Plural.of(report.recharges(), "recharge"));
        stdout.println("Report: " + outDir.resolve("report.json"));
        stdout.flush();
        return report.success() ? 0 : Main.EXIT_MISSION_FAILED;
    }

    /**
     * A world with several robots: every robot's controller in this process, each with its own id
     * (the world's), rows and run, their engines in {@code engine --robot-ids} (docs/deployment.md).
     */
    private int runWorld(WorldSpec worldSpec, OutputDirectory output, ShutdownSignal signal, PrintWriter stdout,
                         PrintWriter err) {
        Path outDir = output.path();
        Timing mode = Timing.of(timing.toLowerCase(Locale.ROOT)).orElseThrow(); // checked by problem()
        String ids = worldSpec.robots().stream().map(r -> String.valueOf(r.id())).collect(Collectors.joining(", "));
        stdout.printf(Locale.ROOT, "World %s: %d robots (ids %s) on %s, %s timing%n", worldSpec.name(),
                worldSpec.robots().size(), ids, DbOptions.redacted(db.url()), mode.label());
        if (spec.commandLine().getParseResult().hasMatchedOption("--robot-id")) {
            stdout.printf(Locale.ROOT, "--robot-id %d is not used: the world gives its robots' ids%n", process.robotId());
        }
        stdout.flush();
        MissionReport report;
        FleetProcess fleet = new FleetProcess(new RobotProcess.Options(worldSpec, db, process.robotId(), mode, realTimeFactor,
                process.logEvery(), process.heartbeat(), noise.level().sensorNoise()), signal);
        McapRecorder.Fleet recorder = null;
        try {
            if (mcap) { // one file, each robot's topics under /robot/ID, as run writes it
                McapRecorder.Fleet opened = McapRecorder.openFleet(outDir.resolve(McapRecorder.FILE_NAME), worldSpec);
                recorder = opened;
                fleet.alsoTo(i -> opened.robot(i)::record);
            }
            report = fleet.run();
        } catch (IOException e) {
            err.println("cannot write " + McapRecorder.FILE_NAME + " in " + outDir + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        } catch (DatabaseWait.Unreachable | StoredMission.Mismatch e) {
            return notRun(e, recorder, output, err);
        }
        try {
            if (recorder != null) {
                recorder.close();
            }
            writeWorldReport(report, outDir.resolve("report.json"));
            fleet.writeReplay(outDir.resolve("replay.html"), report);
        } catch (IOException e) {
            err.println("cannot write the report in " + outDir + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        for (RobotReport r : report.robots()) {
            stdout.printf(Locale.ROOT, "  robot %d: %s, checkpoints %d/%d, %.1f m, %s (%d with robots), battery min %.1f %%, %s%n",
                    r.id(), r.outcome(), r.checkpointsReached(), r.checkpointsTotal(), r.distanceM(),
                    Plural.of(r.collisions(), "collision"), r.robotCollisions(), r.minBattery(),
                    Plural.of(r.engineIterations(), "engine iteration"));
        }
        stdout.printf(Locale.ROOT, "%s: %s, checkpoints %d/%d, %.1f s simulated in %.2f s (%.1fx real time), %s, %.1f m,"
                        + " %s, battery min %.1f %%, %s%n",
                report.world(), report.outcome(), report.checkpointsReached(), report.checkpointsTotal(), report.simTimeS(),
                report.wallTimeS(), report.realTimeFactor(), Plural.of(report.controlSteps(), "robot step"),
                report.distanceM(), Plural.of(report.collisions(), "collision"), report.minBattery(),
                Plural.of(report.recharges(), "recharge"));
        stdout.println("Report: " + outDir.resolve("report.json"));
        stdout.flush();
        return report.success() ? 0 : Main.EXIT_MISSION_FAILED;
    }

    /**
     * report.json of a world with several robots, as {@code run} writes it, without what the robot
     * process cannot know: each robot's rule failures (the robot's user may not read rule_failures).
     */
    static void writeWorldReport(MissionReport report, Path file) throws IOException {
        Gson gson = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();
        JsonObject json = gson.toJsonTree(report).getAsJsonObject();
        JsonArray robots = json.getAsJsonArray("robots");
        for (int i = 0; robots != null && i < robots.size(); i++) {
            robots.get(i).getAsJsonObject().remove("ruleFailures");
        }
        Files.writeString(file, gson.toJson(json) + "\n", StandardCharsets.UTF_8);
    }

    /**
     * The run could not begin: says why, leaves nothing behind.
     *
     * @param e        the database did not answer in time, or holds another world's mission
     * @param recorder run.mcap's recorder, or null
     * @return the exit code: bad input for another world's mission, else the infrastructure's
     */
    private static int notRun(Exception e, AutoCloseable recorder, OutputDirectory output, PrintWriter err) {
        closeQuietly(recorder, output.path());
        output.removeIfEmpty();
        err.println(e.getMessage());
        err.flush();
        return e instanceof StoredMission.Mismatch ? Main.EXIT_BAD_INPUT : Main.EXIT_INFRASTRUCTURE;
    }

    /** A mission that never started leaves no run.mcap behind. */
    private static void closeQuietly(AutoCloseable recorder, Path outDir) {
        if (recorder == null) {
            return;
        }
        try {
            recorder.close();
            Files.deleteIfExists(outDir.resolve(McapRecorder.FILE_NAME));
            Files.deleteIfExists(outDir.resolve(FleetLayout.FILE_NAME));
        } catch (Exception e) {
            // nothing was recorded: nothing to report
        }
    }

    private String problem() {
        String dbProblem = db.problem();
        if (dbProblem != null) {
            return dbProblem;
        }
        if (Timing.of(timing.toLowerCase(Locale.ROOT)).isEmpty()) { // any case here; robot_clock holds the lower-case word
            return "--timing must be sync or realtime: " + timing;
        }
        if (noise.problem() != null) {
            return noise.problem();
        }
        if (!(realTimeFactor > 0) || Double.isInfinite(realTimeFactor)) {
            return "--real-time-factor must be a positive number: " + realTimeFactor;
        }
        return process.problem();
    }
}
