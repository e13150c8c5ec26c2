package org.proactiverobotics.app;

import com.zaxxer.hikari.HikariConfig;
import com.zaxxer.hikari.HikariDataSource;
import java.io.PrintWriter;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.proactiverobotics.app.deploy.DatabaseWait;
import org.proactiverobotics.app.deploy.DbOptions;
import org.proactiverobotics.app.deploy.ProcessOptions;
import org.proactiverobotics.app.deploy.JdbcEngineClock;
import org.proactiverobotics.app.deploy.EngineBodies;
import org.proactiverobotics.app.deploy.EngineLease;
import org.proactiverobotics.app.deploy.EngineLoop;
import org.proactiverobotics.app.deploy.RobotIds;
import org.proactiverobotics.app.deploy.RobotServer;
import org.proactiverobotics.app.deploy.ServiceLogging;
import org.proactiverobotics.app.deploy.ShutdownSignal;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code engine}: the Proactive Engine process of the paper's deployment (docs/command-line.md): the
 * robot's scenarios against a shared database, resuming from the saved state, serving the runs
 * of a robot process until stopped (SIGTERM / Ctrl-C: the current iteration ends, its state is
 * saved, exit 0).
 */
@Command(name = "engine",
        mixinStandardHelpOptions = true,
        description = {"Runs the proactive engine of one robot, or of several (--robot-ids), against a shared database until stopped.",
                "Serves the runs of `robot` processes: one iteration per robot step (sync timing) or one per period (realtime).",
                "Each robot is served by one engine at a time, through its lease row: several engine processes may share a fleet,"
                        + " and one takes over the robots of an engine that died once their leases expire (--lease-s, --standby-ids).",
                "Resumes from the saved state; SIGTERM / Ctrl-C end the current iteration, save and exit 0.",
                "Exit codes: 0 stopped, 2 bad input, 3 database not usable within --wait-s or saved state unreadable."})
public final class EngineCommand implements Callable<Integer> {

    /** The most threads an engine process may be given. */
    private static final int MAX_THREADS = 1000;
    /** A thread per robot, up to this many by default: a thread blocked on a robot's lock costs no processor. */
    private static final int DEFAULT_MAX_THREADS = 16;

    @Mixin
    private DbOptions db;

    @Mixin
    private ProcessOptions process;

    /** --scenarios, --strategy and --strategy-file; the strategy is written when the robot has none yet. */
    @Mixin
    private ScenarioOptions scenarios;

    @Option(names = "--fresh", description = "Discard the saved state and start the scenarios afresh (default: resume).")
    private boolean fresh;

    @Option(names = "--max-speed-mps", paramLabel = "V", defaultValue = "0.5",
            description = "The robot's top wheel speed as the engine assumes it, m/s, for a robot whose process wrote no body"
                    + " (robot_body); given, it overrides every robot's. Default: ${DEFAULT-VALUE}.")
    private double maxSpeedMps;

    @Option(names = "--axle-width-m", paramLabel = "W", defaultValue = "0.24",
            description = "The distance between the robot's wheels, m, for a robot whose process wrote no body (robot_body);"
                    + " given, it overrides every robot's. Default: ${DEFAULT-VALUE}.")
    private double axleWidthM;

    @Option(names = "--period-ms", paramLabel = "MS", defaultValue = "32",
            description = "Real-time timing: one iteration every this many ms. Default: ${DEFAULT-VALUE}.")
    private long periodMs;

    @Option(names = "--robot-ids", paramLabel = "LIST",
            description = "Serve several robots, each with its own state, scenarios and strategy: ids and ranges,"
                    + " e.g. 1-100 or 1,3,7-9 (instead of --robot-id). A robot is taken up when it runs and dropped"
                    + " a minute after its run ended.")
    private String robotIds;

    @Option(names = "--standby-ids", paramLabel = "LIST",
            description = "Robots this engine takes over only when no other engine serves them once they have run"
                    + " for --lease-s (their engine died, or never came): the other engines' robots, for fail-over.")
    private String standbyIds;

    @Option(names = "--threads", paramLabel = "N", defaultValue = "0",
            description = "Threads serving the robots (each owns a share of them; a thread with one robot waits"
                    + " for its steps in the database on MariaDB), at most one per robot. Default (0): the number"
                    + " of robots, at most " + DEFAULT_MAX_THREADS + " or twice the number of cores if more.")
    private int threads;

    @Option(names = "--engine-name", paramLabel = "NAME",
            description = "This engine's name in the robots' leases, unique among the engines sharing a fleet;"
                    + " a restarted engine takes its own leases back at once. Default: the host name and the robot ids.")
    private String engineName;

    @Option(names = "--lease-s", paramLabel = "S", defaultValue = "5",
            description = "How long a robot's lease outlives its engine: another engine takes the robot over after"
                    + " this many seconds without renewal. Default: ${DEFAULT-VALUE}.")
    private double leaseS;



    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        String problem = problem();
        ScenarioOptions.Choice choice = null;
        if (problem == null) {
            try {
                choice = scenarios.load(true); // which robots share a world, each one's body says
            } catch (IllegalArgumentException e) { // a plug-in or strategy that cannot be used
                problem = e.getMessage();
            }
        }
        if (problem != null) {
            err.println(problem);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        if (choice.unlistedWarning() != null) {
            err.println(choice.unlistedWarning());
            err.flush();
        }
        ServiceLogging.statusLines();
        ShutdownSignal signal = ShutdownSignal.install();
        int code = Main.EXIT_INFRASTRUCTURE; // what an unexpected exception ends with
        try {
            code = serve(signal, err, choice);
        } finally {
            signal.finished(code);
        }
        return code;
    }

    private int serve(ShutdownSignal signal, PrintWriter err, ScenarioOptions.Choice choice) {
        try {
            if (!DatabaseWait.await(db, "engine_lease", signal::stopRequested)) {
                return 0;
            }
        } catch (DatabaseWait.Unreachable e) {
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        int[] ids = ids();
        int robots = ids.length + (standbyIds == null ? 0 : RobotIds.parse(standbyIds).length);
        int threadCount = Math.min(robots, threads > 0 ? threads
                : Math.max(DEFAULT_MAX_THREADS, 2 * Runtime.getRuntime().availableProcessors()));
        HikariConfig config = Databases.allowMultiStatements(Databases.config(db.url(), db.user(), db.password()), db.url());
        // per thread: an iteration's connection, a read beside it and the handshake's locks (HandshakeLocks)
        config.setMaximumPoolSize(3 * threadCount + 2);
        config.setMinimumIdle(threadCount + 2); // the rest opened when used, closed when idle
        try (HikariDataSource pool = new HikariDataSource(config)) {
            String name = engineName != null ? engineName : defaultName();
            long leaseMs = Math.round(leaseS * 1000);
            EngineLoop.Options options = new EngineLoop.Options(choice.strategy(), fresh, periodMs, process.logEvery(), leaseMs);
            DriveProfile drive = new DriveProfile(maxSpeedMps, axleWidthM);
            // each robot's own body, as its process wrote it, unless the options say otherwise for all
            RobotServer.Bodies bodies = driveGiven() ? null : new EngineBodies(pool, drive);
            List<RobotServer> servers = new ArrayList<>();
            int[] standby = standbyIds == null ? new int[0] : RobotIds.parse(standbyIds);
            for (int[] group : new int[][] {ids, standby}) {
                for (int id : group) {
                    EngineLease lease = new EngineLease(pool, id, name, leaseMs);
                    ScenarioPlugins plugins = choice.plugins();
                    servers.add(new RobotServer(id, (robot, body) -> RobotEngine.builder().robotId(robot).database(pool)
                            .drive(body.drive()).sharedWorld(body.sharedWorld()).plugins(plugins).guard(lease::confirm).build(), bodies, drive,
                            new JdbcEngineClock(pool, id), lease, options, group == standby, ids.length + standby.length > 1));
                }
            }
            if (ids.length > 1 || standby.length > 0) {
                log().info("engine {}: serving robots {}{} on {} thread(s), lease {} s", name,
                        robotIds == null ? process.robotId() : robotIds,
                        standby.length > 0 ? " (standby for " + standbyIds + ")" : "", threadCount, leaseS);
            }
            new EngineLoop(pool, servers, threadCount, signal::stopRequested, process.heartbeat()).run();
            return 0;
        } catch (CorruptStateException e) {
            err.println("the saved engine state cannot be read: " + e.getMessage()
                    + "\n(start with --fresh to discard it)");
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
    }

    /** @return whether --max-speed-mps or --axle-width-m was given: then it holds for every robot served */
    private boolean driveGiven() {
        var parsed = spec.commandLine().getParseResult();
        return parsed.hasMatchedOption("--max-speed-mps") || parsed.hasMatchedOption("--axle-width-m");
    }

    private int[] ids() {
        return robotIds == null ? new int[] {process.robotId()} : RobotIds.parse(robotIds);
    }

    private String defaultName() {
        String host;
        try {
            host = InetAddress.getLocalHost().getHostName();
        } catch (UnknownHostException e) {
            host = "engine";
        }
        String robots = robotIds == null ? String.valueOf(process.robotId()) : robotIds.replace(" ", "");
        if (robots.length() > 40) { // a long list: its first characters and a hash keep the name short and distinct
            robots = robots.substring(0, 24) + "~" + Integer.toHexString(robots.hashCode());
        }
        String name = host + ":" + robots;
        return name.length() <= 128 ? name : name.substring(name.length() - 128);
    }

    private String problem() {
        String dbProblem = db.problem();
        if (dbProblem != null) {
            return dbProblem;
        }
        if (robotIds != null) {
            if (spec.commandLine().getParseResult().hasMatchedOption("--robot-id")) {
                return "give either --robot-id or --robot-ids, not both";
            }
            try {
                RobotIds.parse(robotIds);
            } catch (IllegalArgumentException e) {
                return e.getMessage();
            }
        }
        if (standbyIds != null) {
            try {
                int[] standby = RobotIds.parse(standbyIds);
                for (int id : ids()) {
                    if (java.util.Arrays.binarySearch(standby, id) >= 0) {
                        return "robot " + id + " is in both the robots served and --standby-ids";
                    }
                }
            } catch (IllegalArgumentException e) {
                return e.getMessage().replace("--robot-ids", "--standby-ids");
            }
        }
        if (threads < 0 || threads > MAX_THREADS) {
            return "--threads must be from 0 (automatic) to " + MAX_THREADS + ": " + threads;
        }
        if (!(leaseS >= 0.5) || leaseS > 3600) {
            return "--lease-s must be between 0.5 and 3600 seconds: " + leaseS;
        }
        if (engineName != null && (engineName.isBlank() || engineName.length() > 128)) {
            return "--engine-name must be 1 to 128 characters: '" + engineName + "'";
        }
        if (!(maxSpeedMps > 0) || Double.isInfinite(maxSpeedMps)) {
            return "--max-speed-mps must be a positive number: " + maxSpeedMps;
        }
        if (!(axleWidthM > 0) || Double.isInfinite(axleWidthM)) {
            return "--axle-width-m must be a positive number: " + axleWidthM;
        }
        if (periodMs < 1) {
            return "--period-ms must be >= 1: " + periodMs;
        }
        return process.problem();
    }

    /**
     * The logger, looked up when first used: a static one would start logback (about 0.2 s) in every command,
     * since picocli makes an instance of each subcommand to build the command line.
     */
    private static Logger log() {
        return LoggerFactory.getLogger(EngineCommand.class);
    }
}
