package org.proactiverobotics.app.mission;

import com.zaxxer.hikari.HikariDataSource;
import java.io.IOException;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;
import java.util.function.Supplier;
import java.util.function.UnaryOperator;
import org.proactiverobotics.app.foxglove.McapRecorder;
import org.proactiverobotics.app.link.DirectEngineTables;
import org.proactiverobotics.app.link.DirectLink;
import org.proactiverobotics.app.replay.ReplayData;
import org.proactiverobotics.app.replay.ReplayPage;
import org.proactiverobotics.app.replay.ReplayRobot;
import org.proactiverobotics.app.replay.SeenReadings;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.robot.RobotConfig;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RobotLink;
import org.proactiverobotics.robot.link.RobotPool;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.SvgRenderer;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The headless mission of a world with several robots (docs/world-file.md, "Several robots"), in one process: one simulation, and
 * per robot an engine (its own state, scenarios, strategy and rows under the robot's id) and a controller. Each
 * step every robot whose mission goes on senses, every such engine iterates, every such robot acts, then the world
 * steps once. A robot whose mission is over (battery flat, a checkpoint unreachable) stops and stays where it is;
 * one that accomplished it steps on while another's mission goes on, its engine taking it out of the others' way
 * ({@link FleetSteps}); the run ends when every robot is done or at the world's time limit.
 * <p>
 * Over the database every engine shares one pool and every controller another (N may be 100). The engines may
 * iterate on several threads ({@code threads}): each touches only its own robot's rows and state, and everything
 * that is written or compared happens on the mission's thread in the robots' order, so the run is the same bit
 * for bit whatever the thread count, and on the direct link, H2 or MariaDB.
 */
final class FleetMission {

    private final MissionOptions options;
    private final int threads;
    private final UnaryOperator<EngineTables> engineTables;
    private final Consumer<Simulation> stepHook;
    private boolean mcap;

    /**
     * @param options      what to run (its world has several robots; {@code robotId} is not used: ids are the world's)
     * @param threads      how many threads iterate the engines (1: the mission's own)
     * @param engineTables wraps each engine's tables before it is built
     * @param stepHook     called after every world step
     */
    FleetMission(MissionOptions options, int threads, UnaryOperator<EngineTables> engineTables,
                 Consumer<Simulation> stepHook) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1: " + threads);
        }
        this.options = options;
        this.threads = threads;
        this.engineTables = engineTables;
        this.stepHook = stepHook;
    }

    /**
     * Also writes run.mcap: one file, each robot's topics under {@code /robot/ID} (docs/foxglove.md).
     *
     * @param enabled whether to
     * @return this
     */
    FleetMission mcap(boolean enabled) {
        this.mcap = enabled;
        return this;
    }

    /**
     * Runs every robot's mission to its end and writes trace.jsonl, replay.html and trajectory.svg.
     *
     * @param outDir where the output goes (must exist)
     * @return the report (the caller writes report.json)
     * @throws SQLException when the database cannot be reached or set up
     * @throws IOException  when the output cannot be written
     */
    MissionReport run(Path outDir) throws SQLException, IOException {
        WorldSpec world = options.world();
        Simulation sim = new Simulation(world, options.noise().sensorNoise());
        List<FleetLane> lanes = new ArrayList<>();
        for (int i = 0; i < world.robots().size(); i++) {
            lanes.add(new FleetLane(i, world.robots().get(i).id(), sim));
        }
        if (options.link() == MissionOptions.Link.DIRECT) {
            DirectLink link = new DirectLink();
            for (FleetLane lane : lanes) {
                DirectEngineTables tables = link.engine(lane.robotId);
                lane.engine = engine(lane).tables(EngineTables.of(tables, tables::pruneHistory), StateStore.none()).build();
            }
            return run(sim, lanes, () -> link, outDir); // the direct link is shared; closing it does nothing
        }
        try (HikariDataSource enginePool = Databases.multiStatementPool(options.jdbcUrl(), options.user(), options.password());
             HikariDataSource robotPool = RobotPool.open(options.jdbcUrl(), options.user(), options.password())) {
            Schema.apply(enginePool);
            try (Connection c = enginePool.getConnection()) {
                for (FleetLane lane : lanes) { // every robot's mission starts from a clean slate
                    RobotRows.delete(c, lane.robotId, Schema.tableNames());
                }
            }
            for (FleetLane lane : lanes) {
                lane.engine = engine(lane).database(enginePool).build();
            }
            return run(sim, lanes, () -> new JdbcRobotLink(robotPool), outDir); // each over the one pool
        }
    }

    /** One robot's engine: its id, its own robot's drive profile, this mission's plug-ins, its own tracer. */
    private RobotEngine.Builder engine(FleetLane lane) {
        WorldSpec.Robot robot = options.world().robots().get(lane.index).robot();
        // each robot shares the world with the others: the map lets moving obstacles go, Yield runs
        return RobotEngine.builder().robotId(lane.robotId).drive(new DriveProfile(robot.maxSpeedMps(), 2 * robot.radiusM()))
                .sharedWorld(true).plugins(options.plugins()).observer(lane::decided).belief(lane.belief)
                .decorate(tables -> SeenReadings.wrap(engineTables.apply(tables), r -> lane.seen = r));
    }

    private MissionReport run(Simulation sim, List<FleetLane> lanes, Supplier<RobotLink> links, Path outDir)
            throws IOException {
        for (FleetLane lane : lanes) {
            lane.engine.startFresh();
            lane.engine.writeStrategy(options.strategy().forSharedWorld()); // Yield right below the collision monitor
            lane.controller = new ProactiveController(sim, lane.index, links.get(),
                    RobotConfig.defaults(lane.robotId));
            lane.controller.onCommand(command -> lane.commandWins.merge(command.scenario(), 1L, Long::sum));
        }
        ExecutorService pool = threads > 1 ? Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "engines");
            t.setDaemon(true);
            return t;
        }) : null;
        try (TraceWriter traceWriter = new TraceWriter(outDir.resolve("trace.jsonl"));
             McapRecorder.Fleet recorder = mcap ? McapRecorder.openFleet(outDir.resolve(McapRecorder.FILE_NAME),
                     options.world()) : null) {
            for (FleetLane lane : lanes) { // the replay's suggestion columns are the engine's slots, as in a one-robot run
                lane.replay = new ReplayData(lane.engine.slots(), sim.robot(lane.index).distanceSensors().size());
                lane.tracer = new StepTracer(sim, lane.index, lane.robotId, traceWriter, lane.replay, lane.belief,
                        recorder == null ? null : recorder.robot(lane.index));
                lane.tracer.seen(lane.seen);
                lane.tracer.slots(lane.engine.slots());
            }
            MissionReport report = loop(sim, lanes, pool);
            writePicture(sim, lanes, outDir.resolve("trajectory.svg"));
            List<ReplayRobot> shown = new ArrayList<>();
            for (FleetLane lane : lanes) {
                shown.add(lane.replayRobot(options.world().robots().get(lane.index), report));
            }
            ReplayPage.writeFleet(outDir.resolve("replay.html"), ReplayPage.Source.RUN, options.world(),
                    ScenarioColours.of(lanes.get(0).engine.slots()), shown,
                    lanes.size() + " robots: " + Mission.summary(report));
            return report;
        } finally {
            if (pool != null) {
                pool.shutdownNow();
            }
            for (FleetLane lane : lanes) {
                if (lane.controller != null) {
                    lane.controller.close();
                }
            }
        }
    }

    private MissionReport loop(Simulation sim, List<FleetLane> lanes, ExecutorService pool) {
        List<FleetLane> active = new ArrayList<>(lanes);
        PoseErrorMeter poseError = new PoseErrorMeter();
        long physicsNs = 0;
        long robotNs = 0;
        long engineNs = 0;
        long steps = 0;
        long start = System.nanoTime();
        while (!active.isEmpty()) {
            long t0 = System.nanoTime();
            for (FleetLane lane : active) {
                lane.controller.sense();
            }
            long t1 = System.nanoTime();
            iterate(active, pool);
            long t2 = System.nanoTime();
            for (FleetLane lane : active) {
                BeliefTracer belief = lane.belief;
                if (belief.hasPose()) { // the world has not moved since the robots sensed: truth is the iteration's
                    GroundTruth truth = sim.groundTruth(lane.index);
                    lane.poseError.add(belief.poseXM(), belief.poseYM(), belief.poseHeadingRad(), truth.x(), truth.y(),
                            truth.headingRad());
                    poseError.add(belief.poseXM(), belief.poseYM(), belief.poseHeadingRad(), truth.x(), truth.y(),
                            truth.headingRad());
                }
                lane.controller.act();
                lane.tracer.beforePhysics();
            }
            long t3 = System.nanoTime();
            sim.step();
            long t4 = System.nanoTime();
            for (FleetLane lane : active) {
                lane.afterStep(sim);
            }
            boolean anyGoesOn = lanes.stream().anyMatch(l -> !l.done());
            active.removeIf(l -> !FleetSteps.steps(l.outcome(), anyGoesOn));
            robotNs += (t1 - t0) + (t3 - t2);
            engineNs += t2 - t1;
            physicsNs += t4 - t3;
            steps++;
            stepHook.accept(sim);
        }
        double wallS = (System.nanoTime() - start) / 1e9;
        return report(sim, lanes, wallS, poseError.result(), MissionReport.Timing.rounded(physicsNs / 1e6 / steps,
                robotNs / 1e6 / steps, engineNs / 1e6 / steps));
    }

    /** Every active engine's iteration: in order on this thread, or spread over the pool and joined. */
    private static void iterate(List<FleetLane> active, ExecutorService pool) {
        if (pool == null) {
            for (FleetLane lane : active) {
                lane.iterate();
            }
            return;
        }
        List<Future<?>> running = new ArrayList<>(active.size());
        for (FleetLane lane : active) {
            running.add(pool.submit(lane::iterate));
        }
        for (Future<?> f : running) {
            try {
                f.get();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while the engines iterated", e);
            } catch (ExecutionException e) {
                if (e.getCause() instanceof RuntimeException r) {
                    throw r;
                }
                throw new IllegalStateException(e.getCause());
            }
        }
    }

    /**
     * The whole run's report: success only when every robot accomplished its mission; the outcome is the first
     * robot's (in the world's order) that did not; counts summed and minima taken over the robots.
     */
    private MissionReport report(Simulation sim, List<FleetLane> lanes, double wallS, PoseError poseError,
                                 MissionReport.Timing timing) {
        List<RobotReport> robots = new ArrayList<>();
        for (FleetLane lane : lanes) {
            robots.add(lane.report(sim));
        }
        List<GroundTruth> truths = new ArrayList<>();
        for (int i = 0; i < lanes.size(); i++) {
            truths.add(sim.groundTruth(i));
        }
        String database = options.link() == MissionOptions.Link.DIRECT ? "direct"
                : MissionReport.databaseKind(options.jdbcUrl());
        return MissionReport.ofRobots(sim, robots, truths, options.strategy().name(), database, wallS, true, poseError,
                timing);
    }

    /** Every robot's path in a colour of its own, a marker at each recharge and where each robot ended. */
    private void writePicture(Simulation sim, List<FleetLane> lanes, Path file) throws IOException {
        WorldSpec world = options.world();
        SvgRenderer svg = new SvgRenderer(world).title(world.name() + " — " + lanes.size() + " robots' paths");
        for (FleetLane lane : lanes) {
            svg.trajectory(lane.path);
            for (SvgRenderer.Marker m : lane.markers) {
                svg.marker(m.x(), m.y(), m.label());
            }
            GroundTruth t = sim.groundTruth(lane.index);
            svg.marker(t.x(), t.y(), "robot " + lane.robotId + " end");
        }
        svg.write(file);
    }
}
