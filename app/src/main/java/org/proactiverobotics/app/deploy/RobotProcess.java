package org.proactiverobotics.app.deploy;

import com.zaxxer.hikari.HikariDataSource;
import java.io.IOException;
import java.nio.file.Path;
import java.sql.SQLException;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import org.proactiverobotics.app.Plural;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.app.mission.ScenarioColours;
import org.proactiverobotics.app.replay.ReplayData;
import org.proactiverobotics.app.replay.ReplayPage;
import org.proactiverobotics.app.replay.RobotTracer;
import org.proactiverobotics.app.replay.TraceStep;
import org.proactiverobotics.db.Backoff;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import org.proactiverobotics.robot.Lockstep;
import org.proactiverobotics.robot.LoopTimes;
import org.proactiverobotics.robot.Missions;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.robot.RobotConfig;
import org.proactiverobotics.robot.StepGate;
import org.proactiverobotics.robot.link.JdbcRobotClock;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RobotPool;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.SensorNoise;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot process: the simulated world and the {@link ProactiveController} in the
 * Webots-style loop, in lockstep (or real time) with an engine process through the database;
 * at the end, the report from the simulator's ground truth, as the one-process mission writes it.
 */
public final class RobotProcess {

    /**
     * @param world          the validated world
     * @param db             the shared database
     * @param robotId        the robot's id in every table
     * @param timing         sync or realtime
     * @param realTimeFactor real-time pacing (1 = real time); unused in sync timing
     * @param logEvery       one INFO line every this many steps
     * @param heartbeat      touched while the robot steps
     * @param noise          the sensors' noise, drawn from the world's seed
     */
    public record Options(WorldSpec world, DbOptions db, int robotId, Timing timing, double realTimeFactor,
                          long logEvery, Heartbeat heartbeat, SensorNoise noise) {

        /** Options with perfect sensors. */
        public Options(WorldSpec world, DbOptions db, int robotId, Timing timing, double realTimeFactor,
                       long logEvery, Heartbeat heartbeat) {
            this(world, db, robotId, timing, realTimeFactor, logEvery, heartbeat, SensorNoise.NONE);
        }
    }

    private static final Logger LOG = LoggerFactory.getLogger(RobotProcess.class);

    private final Options options;
    private final ShutdownSignal signal;
    private final ReplayData replay;
    private Consumer<TraceStep> alsoTo = step -> { };

    /**
     * @param options what to run
     * @param signal  the stop request (SIGTERM / Ctrl-C)
     */
    public RobotProcess(Options options, ShutdownSignal signal) {
        this.options = options;
        this.signal = signal;
        this.replay = new ReplayData(Map.of(), options.world().robot().sensorAnglesDeg().size());
    }

    /**
     * @param sink also receives every step the replay gets (run.mcap's recorder)
     * @return this process
     */
    public RobotProcess alsoTo(Consumer<TraceStep> sink) {
        this.alsoTo = sink;
        return this;
    }

    /**
     * Waits for the database, starts a run, waits for the engine, runs the mission to its end.
     *
     * @return the report; outcome {@link Outcome#STOPPED} when a stop came first
     * @throws DatabaseWait.Unreachable when the database is not usable in time
     */
    public MissionReport run() throws DatabaseWait.Unreachable {
        WorldSpec world = options.world();
        int robotId = options.robotId();
        Simulation sim = new Simulation(world, options.noise());
        RobotTracer tracer = new RobotTracer(sim, replay);
        tracer.alsoTo(alsoTo);
        if (!DatabaseWait.await(options.db(), "robot_clock", signal::stopRequested)) {
            return report(sim, Outcome.STOPPED, 0, null, Map.of(), 0);
        }
        boolean sync = options.timing() == Timing.SYNC;
        RobotConfig config = RobotConfig.defaults(robotId).withRealTimeFactor(sync ? 0 : options.realTimeFactor());
        Map<String, Long> wins = new TreeMap<>();
        try (HikariDataSource pool = RobotPool.open(options.db().url(), options.db().user(), options.db().password());
             JdbcRobotLink link = new JdbcRobotLink(pool);
             ProactiveController robot = new ProactiveController(sim, link, config)) {
            if (!checkStoredMission(pool, robotId, world, false, options, signal)) {
                return report(sim, Outcome.STOPPED, 0, null, Map.of(), 0);
            }
            robot.onCommand(c -> {
                wins.merge(c.scenario(), 1L, Long::sum);
                tracer.command(c);
            });
            signal.onStop(robot::requestStop);
            Lockstep lockstep = new Lockstep(link.clock(), robotId, options.timing(),
                    () -> signal.stopRequested() || robot.stopRequested());
            if (!lockstep.begin()) {
                return report(sim, Outcome.STOPPED, 0, robot.loopTimes(), wins, 0);
            }
            long start = System.nanoTime();
            robot.run(new StatusGate(lockstep, sim, options, tracer));
            double wallS = (System.nanoTime() - start) / 1e9;
            Outcome outcome = outcome(sim, robot.checkpointUnreachable());
            lockstep.finish(outcome == Outcome.STOPPED ? RunState.STOPPED : RunState.FINISHED);
            long iterations = lockstep.lastTick().map(t -> t.iteration()).orElse(0L);
            return report(sim, outcome, wallS, robot.loopTimes(), wins, iterations);
        }
    }

    /**
     * Writes replay.html: what the robot knows, step by step (after {@link #run()}).
     *
     * @param file   where
     * @param report the mission's report
     * @throws IOException when it cannot be written
     */
    public void writeReplay(Path file, MissionReport report) throws IOException {
        String summary = Mission.summary(report) + ", robot process";
        ReplayPage.write(file, ReplayPage.Source.ROBOT, options.world(),
                ScenarioColours.of(RobotEngine.freshSlots(ScenarioPlugins.none())), replay, summary);
    }

    /** The one-process mission's checks; a robot stopped before any of them holds was stopped. */
    private static Outcome outcome(Simulation sim, boolean unreachable) {
        Outcome outcome = Outcome.of(sim, unreachable);
        return outcome == null ? Outcome.STOPPED : outcome;
    }

    private MissionReport report(Simulation sim, Outcome outcome, double wallS, LoopTimes times, Map<String, Long> wins,
                                 long engineIterations) {
        long steps = times == null ? 0 : times.steps();
        MissionReport.Timing timing = times == null ? null
                : MissionReport.Timing.rounded(times.physicsMs(), times.senseMs() + times.actMs(), times.waitMs());
        // strategy and ruleFailures left out: the robot's user may read neither the strategy nor rule_failures table;
        // poseError too: the engine's belief stays in the engine process, no table holds it
        return MissionReport.of(sim, outcome, null, MissionReport.databaseKind(options.db().url()), wallS, steps,
                engineIterations, wins, null, null, timing);
    }

    /** The lockstep gate plus one INFO line every N steps and the heartbeat. */
    private static final class StatusGate implements StepGate {
        private final Lockstep lockstep;
        private final Simulation sim;
        private final Options options;
        private final RobotTracer tracer;
        private final long startNanos = System.nanoTime();

        StatusGate(Lockstep lockstep, Simulation sim, Options options, RobotTracer tracer) {
            this.lockstep = lockstep;
            this.sim = sim;
            this.options = options;
            this.tracer = tracer;
        }

        @Override
        public boolean sensed(long step, long simTimeMs) {
            options.heartbeat().beat();
            tracer.sensed();
            return lockstep.sensed(step, simTimeMs);
        }

        @Override
        public void stepped(long step, long simTimeMs) {
            options.heartbeat().beat();
            tracer.stepped(lockstep.lastTick().map(t -> t.iteration()).orElse(step));
            if (step % options.logEvery() == 0) {
                GroundTruth truth = sim.groundTruth();
                double wallS = (System.nanoTime() - startNanos) / 1e9;
                LOG.info("robot {}: step {}, {} s simulated ({}x real time), checkpoints {}/{}, battery {} %, {} m, {}",
                        options.robotId(), step, String.format(Locale.ROOT, "%.1f", simTimeMs / 1000.0),
                        String.format(Locale.ROOT, "%.1f", simTimeMs / 1000.0 / Math.max(wallS, 1e-9)),
                        truth.checkpointsReached(), truth.checkpointsTotal(),
                        String.format(Locale.ROOT, "%.1f", truth.batteryPct()),
                        String.format(Locale.ROOT, "%.1f", truth.distanceM()), Plural.of(truth.collisions(), "collision"));
            }
        }
    }

    /**
     * Writes the robot's body ({@link RobotBody}) for its engine before its run begins; a database
     * without the table (made before it) gets one warning, and the engine drives by its options.
     *
     * @param pool    the robot's pool
     * @param robotId the robot
     * @param robot   its world file entry
     * @param sharedWorld whether other robots share its world
     * @throws SQLException when the database fails otherwise (the caller retries)
     */
    static void writeBody(HikariDataSource pool, int robotId, WorldSpec.Robot robot, boolean sharedWorld) throws SQLException {
        try {
            RobotBody.write(pool, robotId, RobotBody.of(robot, sharedWorld));
        } catch (SQLException e) {
            if (!EngineBodies.missingOrDenied(e)) {
                throw e;
            }
            LOG.warn("robot {}: robot_body cannot be written ({}): its engine drives by its --max-speed-mps and"
                    + " --axle-width-m (run `db init` to add the table)", robotId, RobotServer.oneLine(e));
        }
    }

    /**
     * A robot may not take over another world's mission rows (see {@link StoredMission}). This is
     * the pool's first use: on a busy machine its first connection can come later than the pool's
     * short wait although the database answers, so a failure waiting can cure is retried after the
     * database is seen to answer again ({@link DatabaseWait}, whose --wait-s bounds only a database
     * that does not answer at all).
     *
     * Then writes the robot's body for its engine. The robot process of a world with several robots
     * ({@link FleetProcess}) prepares each of its robots the same way.
     *
     * @param world       the robot's own world (for a world with several robots, {@link WorldSpec#forRobot})
     * @param sharedWorld whether other robots share its world (its engine then runs Yield)
     * @return true once checked, false when a stop came first
     */
    static boolean checkStoredMission(HikariDataSource pool, int robotId, WorldSpec world, boolean sharedWorld,
                                      Options options, ShutdownSignal signal) throws DatabaseWait.Unreachable {
        Backoff backoff = new Backoff(100, 2_000, System::nanoTime);
        for (int attempt = 1; ; attempt++) {
            try {
                StoredMission.check(pool, robotId, Missions.of(world));
                writeBody(pool, robotId, world.robot(), sharedWorld);
                if (attempt > 1) {
                    LOG.info("robot {}: stored mission read (attempt {})", robotId, attempt);
                }
                return true;
            } catch (SQLException e) {
                DatabaseProblem problem = DatabaseProblem.of(e, options.db().url(), "checkpoints");
                if (!problem.worthWaiting()) {
                    throw new DatabaseWait.Unreachable(problem, problem.message());
                }
                LOG.warn("robot {}: reading the stored mission failed (attempt {}): {}; the database is busy or away:"
                        + " retrying once it answers", robotId, attempt, problem.message());
                backoff.failed();
                while (!backoff.ready()) {
                    if (signal.stopRequested()) {
                        return false;
                    }
                    LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
                }
                if (!DatabaseWait.await(options.db(), "checkpoints", signal::stopRequested)) {
                    return false;
                }
            }
        }
    }
}
