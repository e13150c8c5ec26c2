package org.proactiverobotics.app.mission;

import com.zaxxer.hikari.HikariDataSource;
import java.io.IOException;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;
import org.proactiverobotics.app.Plural;
import org.proactiverobotics.app.link.DirectEngineTables;
import org.proactiverobotics.app.foxglove.McapRecorder;
import org.proactiverobotics.app.link.DirectLink;
import org.proactiverobotics.app.replay.ReplayData;
import org.proactiverobotics.app.replay.ReplayPage;
import org.proactiverobotics.app.replay.SeenReadings;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.IterationSummary;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.robot.RobotConfig;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.SvgRenderer;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * One headless mission in one process, in lockstep: each control step the robot answers the
 * engine's sensor requests, the engine runs one iteration, the robot reads the newest command
 * and sets its wheels, and the world steps. Both sides talk only through the database, each
 * with a pool of its own, exactly as two processes would; or, with
 * {@link MissionOptions.Link#DIRECT}, through an in-process link with the same semantics and no
 * database (what the middleware costs is the difference). Deterministic: the same world and
 * seed give the same run, whichever the layer. A world with several robots runs as a
 * {@link FleetMission}: one world, an engine and a controller per robot.
 */
public final class Mission {

    private final MissionOptions options;
    private final List<SvgRenderer.TrajectoryPoint> path = new ArrayList<>();
    private final List<SvgRenderer.Marker> markers = new ArrayList<>();
    private final Map<String, Long> commandWins = new TreeMap<>();
    private Consumer<Simulation> stepHook = sim -> { };
    private UnaryOperator<EngineTables> engineTables = UnaryOperator.identity();
    private StepTracer tracer;
    private final BeliefTracer belief = new BeliefTracer();
    private final PoseErrorMeter poseError = new PoseErrorMeter();
    private SeenReadings seen;
    private String drivingScenario = "none";
    private Map<String, Integer> slots = Map.of();
    private boolean mcap;
    private int threads = 1;

    /** @param options what to run */
    public Mission(MissionOptions options) {
        this.options = options;
    }

    /**
     * Called after every control step with the simulation (a progress line, a test that changes
     * the strategy mid-run, ...).
     *
     * @param hook the callback
     * @return this mission
     */
    public Mission onStep(Consumer<Simulation> hook) {
        this.stepHook = hook;
        return this;
    }

    /**
     * Wraps what the engine's rules read and write before the engine is built: fault injection
     * in tests (a table that throws for one scenario), a recorder, ...
     *
     * @param decorator takes the engine's tables, returns what the engine gets
     * @return this mission
     */
    public Mission engineTables(UnaryOperator<EngineTables> decorator) {
        this.engineTables = decorator;
        return this;
    }

    /**
     * Also writes run.mcap (the run for Foxglove, docs/foxglove.md) beside trace.jsonl.
     *
     * @param enabled whether to
     * @return this mission
     */
    public Mission mcap(boolean enabled) {
        this.mcap = enabled;
        return this;
    }

    /**
     * How many threads iterate the engines of a world with several robots (the run is the same whatever the count;
     * a one-robot world ignores it).
     *
     * @param count at least 1
     * @return this mission
     */
    public Mission threads(int count) {
        if (count < 1) {
            throw new IllegalArgumentException("threads must be at least 1: " + count);
        }
        this.threads = count;
        return this;
    }

    /**
     * Runs the mission to its end and writes report.json's content (returned), trace.jsonl,
     * replay.html, trajectory.svg and, with {@link #mcap}, run.mcap into the output directory.
     *
     * @param outDir where the trace and the picture go (must exist)
     * @return the report
     * @throws SQLException when the database cannot be reached or set up
     * @throws IOException  when the output cannot be written
     */
    public MissionReport run(Path outDir) throws SQLException, IOException {
        if (options.world().hasSeveralRobots()) {
            return new FleetMission(options, threads, engineTables, stepHook).mcap(mcap).run(outDir);
        }
        if (options.link() == MissionOptions.Link.DIRECT) {
            return runDirect(outDir);
        }
        WorldSpec world = options.world();
        int robotId = options.robotId();
        try (HikariDataSource enginePool = Databases.multiStatementPool(options.jdbcUrl(), options.user(), options.password())) {
            Schema.apply(enginePool);
            clearRobotRows(enginePool, robotId);

            Simulation sim = new Simulation(world, options.noise().sensorNoise());
            RobotEngine engine = engine().database(enginePool).build();
            engine.startFresh();
            engine.writeStrategy(options.strategy());

            try (ProactiveController controller = ProactiveController.connect(sim, options.jdbcUrl(), options.user(),
                    options.password(), RobotConfig.defaults(robotId))) {
                return run(sim, engine, controller, outDir);
            }
        }
    }

    /** The same mission over an in-process link: no database, the engine's state not saved. */
    private MissionReport runDirect(Path outDir) throws IOException {
        WorldSpec world = options.world();
        int robotId = options.robotId();
        DirectLink link = new DirectLink();
        DirectEngineTables tables = link.engine(robotId);
        Simulation sim = new Simulation(world, options.noise().sensorNoise());
        RobotEngine engine = engine().tables(EngineTables.of(tables, tables::pruneHistory), StateStore.none()).build();
        engine.startFresh();
        engine.writeStrategy(options.strategy());
        try (ProactiveController controller = new ProactiveController(sim, link, RobotConfig.defaults(robotId))) {
            return run(sim, engine, controller, outDir);
        }
    }

    /** The engine's standard wiring, with this mission's robot, plug-ins, trace and table wrapper. */
    private RobotEngine.Builder engine() {
        return RobotEngine.builder().robotId(options.robotId()).drive(profile(options.world()))
                .plugins(options.plugins()).observer(this::decided).belief(belief)
                .decorate(tables -> SeenReadings.wrap(engineTables.apply(tables), r -> seen = r));
    }

    private MissionReport run(Simulation sim, RobotEngine engine, ProactiveController controller, Path outDir)
            throws IOException {
        this.slots = engine.slots();
        // Counted as the robot gets them, as the robot process counts them: the same commandWins either way.
        controller.onCommand(command -> {
            commandWins.merge(command.scenario(), 1L, Long::sum);
            drivingScenario = command.scenario();
        });
        ReplayData replay = new ReplayData(slots, sim.robot().distanceSensors().size());
        try (TraceWriter traceWriter = new TraceWriter(outDir.resolve("trace.jsonl"));
             McapRecorder recorder = mcap ? McapRecorder.open(outDir.resolve(McapRecorder.FILE_NAME), options.world()) : null) {
            this.tracer = new StepTracer(sim, traceWriter, replay, belief, recorder);
            tracer.seen(seen);
            tracer.slots(slots);
            MissionReport report = loop(sim, engine, controller);
            writePicture(options.world(), sim, outDir.resolve("trajectory.svg"));
            ReplayPage.write(outDir.resolve("replay.html"), ReplayPage.Source.RUN, options.world(),
                    ScenarioColours.of(slots), replay, summary(report));
            return report;
        }
    }

    private static DriveProfile profile(WorldSpec world) {
        return new DriveProfile(world.robot().maxSpeedMps(), 2 * world.robot().radiusM());
    }

    private MissionReport loop(Simulation sim, RobotEngine engine, ProactiveController controller) {
        GroundTruth truth = sim.groundTruth();
        long physicsNs = 0;
        long robotNs = 0;
        long engineNs = 0;
        long failures = 0;
        long steps = 0;
        int recharges = truth.recharges();
        Outcome outcome;
        long start = System.nanoTime();
        path.add(new SvgRenderer.TrajectoryPoint(truth.x(), truth.y(), drivingScenario));
        while (true) {
            long t0 = System.nanoTime();
            controller.sense();
            long t1 = System.nanoTime();
            IterationSummary summary = engine.iterate();
            failures += summary.rulesFailed();
            long t2 = System.nanoTime();
            if (belief.hasPose()) { // the world has not moved since the robot sensed: truth is the iteration's
                poseError.add(belief.poseXM(), belief.poseYM(), belief.poseHeadingRad(), truth.x(), truth.y(),
                        truth.headingRad());
            }
            controller.act();
            tracer.beforePhysics();
            long t3 = System.nanoTime();
            sim.step();
            long t4 = System.nanoTime();
            tracer.afterPhysics(engine.engine().memory(), engine.engine().lastIterationFailures());
            robotNs += (t1 - t0) + (t3 - t2);
            engineNs += t2 - t1;
            physicsNs += t4 - t3;
            steps++;
            path.add(new SvgRenderer.TrajectoryPoint(truth.x(), truth.y(), drivingScenario));
            if (truth.recharges() > recharges) {
                recharges = truth.recharges();
                markers.add(new SvgRenderer.Marker(truth.x(), truth.y(), "recharge " + recharges));
            }
            stepHook.accept(sim);
            outcome = Outcome.of(sim, controller.checkpointUnreachable());
            if (outcome != null) {
                break;
            }
        }
        double wallS = (System.nanoTime() - start) / 1e9;
        String database = options.link() == MissionOptions.Link.DIRECT ? "direct"
                : MissionReport.databaseKind(options.jdbcUrl());
        return MissionReport.of(sim, outcome, options.strategy().name(), database, wallS, steps, engine.engine().iteration(),
                commandWins, failures, poseError.result(), MissionReport.Timing.rounded(physicsNs / 1e6 / steps,
                        robotNs / 1e6 / steps, engineNs / 1e6 / steps));
    }

    /** Every decision goes to trace.jsonl (the command it leads to is sent in the next iteration). */
    private void decided(long iteration, CommandArray suggestions, Suggestion winner) {
        tracer.decided(iteration, suggestions, winner);
    }

    /** The replay's subtitle: how the mission went, as the command line's summary says it. */
    public static String summary(MissionReport r) {
        return String.format(Locale.ROOT, "%s, checkpoints %d/%d, %.1f s simulated, %s%s",
                r.outcome(), r.checkpointsReached(), r.checkpointsTotal(), r.simTimeS(),
                Plural.of(r.collisions(), "collision"),
                r.strategy() == null ? "" : ", strategy " + r.strategy());
    }

    private void writePicture(WorldSpec world, Simulation sim, Path file) throws IOException {
        SvgRenderer svg = new SvgRenderer(world).robot(sim).trajectory(path)
                .title(world.name() + " — path coloured by the scenario whose command was driving");
        ScenarioColours.of(slots).forEach(svg::colour);
        for (SvgRenderer.Marker m : markers) {
            svg.marker(m.x(), m.y(), m.label());
        }
        svg.write(file);
    }

    /** A mission starts from a clean slate for its robot: earlier rows of the same robot id go. */
    private static void clearRobotRows(HikariDataSource pool, int robotId) throws SQLException {
        try (Connection c = pool.getConnection()) {
            RobotRows.delete(c, robotId, Schema.tableNames());
        }
    }
}
