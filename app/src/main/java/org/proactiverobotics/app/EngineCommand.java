package org.proactiverobotics.app;

import com.zaxxer.hikari.HikariDataSource;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import org.proactiverobotics.app.deploy.DatabaseWait;
import org.proactiverobotics.app.deploy.DbOptions;
import org.proactiverobotics.app.deploy.ProcessOptions;
import org.proactiverobotics.app.deploy.EngineClock;
import org.proactiverobotics.app.deploy.EngineLoop;
import org.proactiverobotics.app.deploy.ServiceLogging;
import org.proactiverobotics.app.deploy.ShutdownSignal;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.robot.RobotEngine;
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
        description = {"Runs the proactive engine of one robot against a shared database until stopped.",
                "Serves the runs of a `robot` process: one iteration per robot step (sync timing) or one per period (realtime).",
                "Resumes from the saved state; SIGTERM / Ctrl-C end the current iteration, save and exit 0.",
                "Exit codes: 0 stopped, 2 bad input, 3 database not usable within --wait-s or saved state unreadable."})
public final class EngineCommand implements Callable<Integer> {

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
            description = "The robot's top wheel speed as the engine assumes it, m/s. Default: ${DEFAULT-VALUE}.")
    private double maxSpeedMps;

    @Option(names = "--axle-width-m", paramLabel = "W", defaultValue = "0.24",
            description = "The distance between the robot's wheels, m. Default: ${DEFAULT-VALUE}.")
    private double axleWidthM;

    @Option(names = "--period-ms", paramLabel = "MS", defaultValue = "32",
            description = "Real-time timing: one iteration every this many ms. Default: ${DEFAULT-VALUE}.")
    private long periodMs;



    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        String problem = problem();
        ScenarioOptions.Choice choice = null;
        if (problem == null) {
            try {
                choice = scenarios.load();
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
            if (!DatabaseWait.await(db, "engine_clock", signal::stopRequested)) {
                return 0;
            }
        } catch (DatabaseWait.Unreachable e) {
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        try (HikariDataSource pool = Databases.pool(db.url(), db.user(), db.password())) {
            RobotEngine side = RobotEngine.builder().robotId(process.robotId()).database(pool)
                    .drive(new DriveProfile(maxSpeedMps, axleWidthM)).plugins(choice.plugins()).build();
            EngineLoop loop = new EngineLoop(side, new EngineClock(pool, process.robotId()), process.robotId(),
                    new EngineLoop.Options(choice.strategy(), fresh, periodMs, process.logEvery()), signal::stopRequested,
                    process.heartbeat());
            loop.run();
            return 0;
        } catch (CorruptStateException e) {
            err.println("the saved engine state cannot be read: " + e.getMessage()
                    + "\n(start with --fresh to discard it)");
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
    }

    private String problem() {
        String dbProblem = db.problem();
        if (dbProblem != null) {
            return dbProblem;
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
}
