package org.proactiverobotics.app.deploy;

import com.zaxxer.hikari.HikariDataSource;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import java.util.function.IntFunction;
import org.proactiverobotics.app.Plural;
import org.proactiverobotics.app.mission.FleetSteps;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.ScenarioColours;
import org.proactiverobotics.app.replay.ReplayData;
import org.proactiverobotics.app.replay.ReplayPage;
import org.proactiverobotics.app.replay.ReplayRobot;
import org.proactiverobotics.app.replay.RobotTracer;
import org.proactiverobotics.app.replay.TraceStep;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.app.mission.RobotReport;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.robot.RobotConfig;
import org.proactiverobotics.robot.WorldLockstep;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.JdbcWorldClock;
import org.proactiverobotics.robot.link.RobotPool;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot process of a world with several robots (docs/deployment.md, "One world, several robots"): one simulated world and,
 * Webots-style, one {@link ProactiveController} per robot, each with its own robot id, rows and run,
 * driven by their engines through the database ({@code engine --robot-ids}, one process or several
 * sharing the robots by lease). Each step every robot whose mission goes on senses, the world's
 * {@link WorldLockstep} publishes their step and (sync timing) waits until every one of their
 * engines served it, every such robot acts, then the world steps once; a robot whose mission ended
 * stands still, a body the others see, except one that accomplished it while others go on: it steps on, its
 * engine taking it out of their way ({@link FleetSteps}). This is {@code run}'s loop for such a world, with the engines
 * in another process: in sync timing the run is {@code run}'s, step for step. At the end, the report
 * from the simulator's ground truth, with every robot's own part.
 */
public final class FleetProcess {

    private static final Logger LOG = LoggerFactory.getLogger(FleetProcess.class);

    private final RobotProcess.Options options;
    private final ShutdownSignal signal;
    /** Each robot's steps also go here (run.mcap's recorder), by the robot's position; null: nowhere. */
    private IntFunction<Consumer<TraceStep>> alsoTo;

    /**
     * @param options what to run ({@code robotId} is not used: the ids are the world's)
     * @param signal  the stop request (SIGTERM / Ctrl-C)
     */
    public FleetProcess(RobotProcess.Options options, ShutdownSignal signal) {
        if (!options.world().hasSeveralRobots()) {
            throw new IllegalArgumentException("world " + options.world().name() + " has one robot: RobotProcess runs it");
        }
        this.options = options;
        this.signal = signal;
        this.lanes = new ArrayList<>();
        for (int i = 0; i < options.world().robots().size(); i++) {
            WorldSpec.RobotEntry entry = options.world().robots().get(i);
            lanes.add(new Lane(i, entry.id(), new ReplayData(Map.of(), entry.robot().sensorAnglesDeg().size())));
        }
    }

    /**
     * @param sinks each robot's steps also go to the sink for its position among the world's robots (run.mcap's recorder)
     * @return this
     */
    public FleetProcess alsoTo(IntFunction<Consumer<TraceStep>> sinks) {
        this.alsoTo = sinks;
        return this;
    }

    /**
     * Writes replay.html: what each of the world's robots knew, step by step (after {@link #run()}),
     * every robot drawn as {@code run} draws such a world ({@code #robot=N&iteration=M}).
     *
     * @param file   where
     * @param report the run's report
     * @throws IOException when it cannot be written
     */
    public void writeReplay(Path file, MissionReport report) throws IOException {
        WorldSpec world = options.world();
        List<ReplayRobot> shown = new ArrayList<>();
        for (Lane lane : lanes) {
            RobotReport mine = report.robots().stream().filter(r -> r.id() == lane.robotId).findFirst().orElseThrow();
            shown.add(mine.replayRobot(world.robots().get(lane.index), lane.replay));
        }
        ReplayPage.writeFleet(file, ReplayPage.Source.ROBOT, world,
                ScenarioColours.of(RobotEngine.freshSlots(ScenarioPlugins.none(), true)), shown,
                lanes.size() + " robots: " + Mission.summary(report) + ", robot process");
    }

    /** One robot of the world: its controller and what its part of the report and its replay gather. */
    private static final class Lane {
        final int index;
        final int robotId;
        final Map<String, Long> commandWins = new TreeMap<>();
        /** What the robot knew, step by step: its part of replay.html. */
        final ReplayData replay;
        RobotTracer tracer;
        ProactiveController controller;
        long controlSteps;
        Outcome outcome;
        long endSimTimeMs;
        /** Whether it takes steps ({@link FleetSteps}): its engine is published the end of its run once it does not. */
        boolean stepping = true;

        Lane(int index, int robotId, ReplayData replay) {
            this.index = index;
            this.robotId = robotId;
            this.replay = replay;
        }
    }

    /** The world's robots, in the world file's order. */
    private final List<Lane> lanes;

    /**
     * Waits for the database, starts every robot's run, waits for their engines, runs the world to
     * the end of every mission (or the time limit).
     *
     * @return the report; outcome {@link Outcome#STOPPED} when a stop came first
     * @throws DatabaseWait.Unreachable when the database is not usable in time
     */
    public MissionReport run() throws DatabaseWait.Unreachable {
        WorldSpec world = options.world();
        Simulation sim = new Simulation(world, options.noise());
        int[] ids = new int[world.robots().size()];
        for (Lane lane : lanes) {
            ids[lane.index] = lane.robotId;
            lane.tracer = new RobotTracer(sim, lane.index, lane.replay);
            if (alsoTo != null) {
                lane.tracer.alsoTo(alsoTo.apply(lane.index));
            }
        }
        if (!DatabaseWait.await(options.db(), "robot_clock", signal::stopRequested)) {
            return report(sim, lanes, null, 0, null);
        }
        boolean sync = options.timing() == Timing.SYNC;
        try (HikariDataSource pool = RobotPool.open(options.db().url(), options.db().user(), options.db().password())) {
            try {
                JdbcRobotLink[] links = new JdbcRobotLink[lanes.size()];
                for (Lane lane : lanes) {
                    // its engine runs Yield, as run's does
                    if (!RobotProcess.checkStoredMission(pool, lane.robotId, world.forRobot(lane.index), true, options, signal)) {
                        return report(sim, lanes, null, 0, null);
                    }
                    links[lane.index] = new JdbcRobotLink(pool);
                    lane.controller = new ProactiveController(sim, lane.index, links[lane.index],
                            RobotConfig.defaults(lane.robotId));
                    lane.controller.onCommand(c -> {
                        lane.commandWins.merge(c.scenario(), 1L, Long::sum);
                        lane.tracer.command(c);
                    });
                }
                // in sync timing each robot's newest command and requests come with the engines' ticks: no reads of their own
                WorldLockstep lockstep = new WorldLockstep(new JdbcWorldClock(pool, ids, sync ? links : null), ids, options.timing(),
                        signal::stopRequested, i -> !lanes.get(i).stepping);
                LOG.info("world {}: {} robots ({}), {} timing", world.name(), ids.length, idList(ids), options.timing().label());
                if (!lockstep.begin()) {
                    return report(sim, lanes, lockstep, 0, null);
                }
                long start = System.nanoTime();
                MissionReport.Timing timing = loop(sim, lanes, lockstep, sync ? 0 : options.realTimeFactor());
                double wallS = (System.nanoTime() - start) / 1e9;
                boolean stopped = lanes.stream().anyMatch(l -> l.outcome == null);
                lockstep.finish(stopped ? RunState.STOPPED : RunState.FINISHED);
                return report(sim, lanes, lockstep, wallS, timing);
            } finally {
                for (Lane lane : lanes) {
                    if (lane.controller != null) {
                        lane.controller.close();
                    }
                }
            }
        }
    }

    /** The loop of {@code run}'s fleet mission, the engines' iterations replaced by the handshake. */
    private MissionReport.Timing loop(Simulation sim, List<Lane> lanes, WorldLockstep lockstep, double realTimeFactor) {
        List<Lane> active = new ArrayList<>(lanes);
        long robotNs = 0;
        long waitNs = 0;
        long physicsNs = 0;
        long step = 0;
        long startNanos = System.nanoTime();
        long startSimMs = sim.simTimeMs();
        while (!active.isEmpty() && !signal.stopRequested()) {
            long t0 = System.nanoTime();
            for (Lane lane : active) {
                lane.controller.sense();
            }
            long t1 = System.nanoTime();
            for (Lane lane : active) {
                lane.tracer.sensed();
            }
            if (!lockstep.sensed(step + 1, sim.simTimeMs())) {
                break;
            }
            step++;
            long t2 = System.nanoTime();
            for (Lane lane : active) {
                lane.controller.act();
            }
            long t3 = System.nanoTime();
            sim.step();
            long t4 = System.nanoTime();
            for (Lane lane : active) {
                lane.tracer.stepped(lockstep.lastTick(lane.index).map(t -> t.iteration()).orElse(step));
                lane.controlSteps++;
                if (lane.outcome != null) {
                    continue; // accomplished, stepping on out of the others' way: its outcome and end time stay
                }
                lane.outcome = Outcome.of(sim, lane.index, lane.controller.checkpointUnreachable());
                if (lane.outcome != null) {
                    lane.endSimTimeMs = sim.simTimeMs();
                    if (lane.outcome != Outcome.MISSION_ACCOMPLISHED) {
                        sim.robot(lane.index).setWheelSpeeds(0.0, 0.0); // over: it stays where it is, a body the others see
                    }
                    LOG.info("robot {}: {} at {} s simulated", lane.robotId, lane.outcome,
                            String.format(Locale.ROOT, "%.1f", lane.endSimTimeMs / 1000.0));
                }
            }
            boolean anyGoesOn = lanes.stream().anyMatch(l -> l.outcome == null);
            for (Lane lane : active) {
                lane.stepping = FleetSteps.steps(lane.outcome, anyGoesOn);
            }
            active.removeIf(l -> !l.stepping);
            robotNs += (t1 - t0) + (t3 - t2);
            waitNs += t2 - t1;
            physicsNs += t4 - t3;
            options.heartbeat().beat();
            if (step % options.logEvery() == 0) {
                status(sim, lanes, step, (System.nanoTime() - startNanos) / 1e9);
            }
            if (realTimeFactor > 0) {
                long due = startNanos + (long) ((sim.simTimeMs() - startSimMs) * 1_000_000L / realTimeFactor);
                long wait = due - System.nanoTime();
                if (wait > 0) {
                    LockSupport.parkNanos(wait);
                }
            }
        }
        for (Lane lane : lanes) {
            sim.robot(lane.index).setWheelSpeeds(0.0, 0.0);
        }
        double n = Math.max(1, step);
        return MissionReport.Timing.rounded(physicsNs / 1e6 / n, robotNs / 1e6 / n, waitNs / 1e6 / n);
    }

    /** One line for the world, then one per robot, as the one-robot process's status line says it. */
    private static void status(Simulation sim, List<Lane> lanes, long step, double wallS) {
        double simS = sim.simTimeMs() / 1000.0;
        LOG.info("world: step {}, {} s simulated ({}x real time)", step, String.format(Locale.ROOT, "%.1f", simS),
                String.format(Locale.ROOT, "%.1f", simS / Math.max(wallS, 1e-9)));
        for (Lane lane : lanes) {
            GroundTruth truth = sim.groundTruth(lane.index);
            LOG.info("robot {}: step {}, {} s simulated, checkpoints {}/{}, battery {} %, {} m, {}{}", lane.robotId,
                    lane.controlSteps, String.format(Locale.ROOT, "%.1f", simS), truth.checkpointsReached(),
                    truth.checkpointsTotal(), String.format(Locale.ROOT, "%.1f", truth.batteryPct()),
                    String.format(Locale.ROOT, "%.1f", truth.distanceM()), Plural.of(truth.collisions(), "collision"),
                    lane.outcome == null ? "" : ", " + lane.outcome);
        }
    }

    /**
     * The whole run's report, as {@code run} sums it (success only when every robot accomplished its
     * mission; the outcome the first robot's that did not; sums and minima over the robots), without
     * what this process cannot see: the strategy, the rule failures and the engines' beliefs.
     */
    private MissionReport report(Simulation sim, List<Lane> lanes, WorldLockstep lockstep, double wallS,
                                 MissionReport.Timing timing) {
        List<RobotReport> robots = new ArrayList<>();
        List<GroundTruth> truths = new ArrayList<>();
        for (Lane lane : lanes) {
            GroundTruth t = sim.groundTruth(lane.index);
            Outcome end = lane.outcome != null ? lane.outcome : Outcome.STOPPED;
            long endMs = lane.outcome != null ? lane.endSimTimeMs : sim.simTimeMs();
            long laneIterations = lockstep == null ? 0 : lockstep.lastTick(lane.index).map(k -> k.iteration()).orElse(0L);
            robots.add(RobotReport.of(lane.robotId, t, end, endMs, lane.controlSteps, laneIterations,
                    lane.commandWins, 0, null));
            truths.add(t);
        }
        return MissionReport.ofRobots(sim, robots, truths, null, MissionReport.databaseKind(options.db().url()), wallS,
                false, null, timing);
    }

    private static String idList(int[] ids) {
        StringBuilder sb = new StringBuilder(ids.length == 1 ? "id " : "ids ");
        for (int i = 0; i < ids.length; i++) {
            sb.append(i == 0 ? "" : ", ").append(ids[i]);
        }
        return sb.toString();
    }
}
