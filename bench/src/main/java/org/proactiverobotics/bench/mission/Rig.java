package org.proactiverobotics.bench.mission;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.function.UnaryOperator;
import javax.sql.DataSource;
import org.proactiverobotics.app.link.DirectEngineTables;
import org.proactiverobotics.app.link.DirectLink;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.engine.Algorithm;
import org.proactiverobotics.engine.IterationListener;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.robot.IterationBatch;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.InitialPose;
import org.proactiverobotics.engine.tables.Station;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.robot.RobotConfig;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RobotPool;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.SensorNoise;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * One robot, wired as {@code Mission} wires it, stepped from outside: each {@link #step()} is the
 * robot's sense, one engine iteration, the robot's act and one physics step. The engine side is
 * the production {@link RobotEngine} (over the database: one transaction per iteration, history
 * pruned every 100 iterations) and, over the database, the robot has a pool of
 * its own ({@link RobotPool}, as a robot process has) with the default retention policy.
 *
 * <p>For endless runs, {@link #rearm()} starts a new lap once the engine has marked every
 * checkpoint reached (over the database: the {@code reached} flags are reset by SQL, outside the
 * timed step; over the direct link: the engine's mission table is wrapped so that it forgets its
 * marks once all are reached).
 */
final class Rig implements AutoCloseable {

    final int robotId;
    final WorldSpec world;
    final Simulation sim;
    private final ProactiveController controller;
    /** The engine side, for a snapshot read ahead with other robots' ({@link #stepAll}). */
    private final RobotEngine engine;
    private final DataSource rearmPool;
    private final Laps laps;
    private final AutoCloseable owned;
    long robotNs;
    long engineNs;
    long physicsNs;
    long steps;
    long lapsDone;
    /** Engine iterations that threw (rolled back; the engine goes on, as the engine process's loop does). */
    long failedIterations;
    String lastFailure;

    private Rig(int robotId, WorldSpec world, Simulation sim, ProactiveController controller,
                RobotEngine engine, DataSource rearmPool, Laps laps, AutoCloseable owned) {
        this.robotId = robotId;
        this.engine = engine;
        this.world = world;
        this.sim = sim;
        this.controller = controller;
        this.rearmPool = rearmPool;
        this.laps = laps;
        this.owned = owned;
    }

    /**
     * A robot over a shared database, its engine built by the production {@link RobotEngine}.
     *
     * @param enginePool the engine side's pool (schema applied); may be shared by many rigs
     * @param jdbcUrl    the database, for the robot's own pool
     */
    static Rig jdbc(WorldSpec world, int robotId, DataSource enginePool, String jdbcUrl, String user, String password)
            throws SQLException {
        return jdbc(world, robotId, enginePool, jdbcUrl, user, password, Algorithm.LAZY);
    }

    /** As {@link #jdbc(WorldSpec, int, DataSource, String, String, String)}, the engine running the given algorithm. */
    static Rig jdbc(WorldSpec world, int robotId, DataSource enginePool, String jdbcUrl, String user, String password,
                    Algorithm algorithm) throws SQLException {
        return jdbc(world, robotId, enginePool, jdbcUrl, user, password, algorithm, UnaryOperator.identity());
    }

    /** As above, the tables the rules see wrapped (a counter of the rules' reads). */
    static Rig jdbc(WorldSpec world, int robotId, DataSource enginePool, String jdbcUrl, String user, String password,
                    Algorithm algorithm, UnaryOperator<EngineTables> decorate) throws SQLException {
        prepare(enginePool, robotId);
        RobotEngine engine = start(RobotEngine.builder().database(enginePool).decorate(decorate), world, robotId, algorithm);
        Simulation sim = new Simulation(world);
        var robotPool = RobotPool.open(jdbcUrl, user, password);
        ProactiveController controller = new ProactiveController(sim, new JdbcRobotLink(robotPool), RobotConfig.defaults(robotId));
        return new Rig(robotId, world, sim, controller, engine, enginePool, null, robotPool);
    }

    /** A robot over an in-process link of its own (no database, the engine's state not saved). */
    static Rig direct(WorldSpec world, int robotId, Algorithm algorithm) {
        return direct(world, robotId, algorithm, SensorNoise.NONE, null);
    }

    /** As above, its sensors erring as the noise says, each iteration and rule told to a listener (or null). */
    static Rig direct(WorldSpec world, int robotId, Algorithm algorithm, SensorNoise noise, IterationListener listener) {
        DirectLink link = new DirectLink();
        DirectEngineTables tables = link.engine(robotId);
        Laps laps = new Laps(tables);
        EngineTables wired = new EngineTables(tables, tables, laps, tables, tables, tables::pruneHistory, tables);
        RobotEngine.Builder builder = RobotEngine.builder().tables(wired, StateStore.none());
        if (listener != null) {
            builder.listener(listener);
        }
        RobotEngine engine = start(builder, world, robotId, algorithm);
        Simulation sim = new Simulation(world, noise);
        ProactiveController controller = new ProactiveController(sim, link, RobotConfig.defaults(robotId));
        return new Rig(robotId, world, sim, controller, engine, null, laps, null);
    }

    /** The production wiring, started fresh with the default strategy, as Mission starts it. */
    private static RobotEngine start(RobotEngine.Builder builder, WorldSpec world, int robotId, Algorithm algorithm) {
        RobotEngine engine = builder.robotId(robotId).drive(profile(world)).algorithm(algorithm).build();
        engine.startFresh();
        engine.writeStrategy(Strategy.named(Strategy.SAFETY_FIRST));
        return engine;
    }

    private static DriveProfile profile(WorldSpec world) {
        return new DriveProfile(world.robot().maxSpeedMps(), 2 * world.robot().radiusM());
    }

    /** As Mission does: the schema and a clean slate for this robot id. */
    private static void prepare(DataSource pool, int robotId) throws SQLException {
        Schema.apply(pool);
        try (Connection c = pool.getConnection()) {
            RobotRows.delete(c, robotId, Schema.tableNames());
        }
    }

    /** One control step, timed by part; returns its wall time, ns. */
    long step() {
        long t0 = System.nanoTime();
        controller.sense();
        long t1 = System.nanoTime();
        try {
            engine.iterate();
        } catch (RuntimeException e) {
            failedIterations++;
            lastFailure = e.getMessage();
        }
        long t2 = System.nanoTime();
        controller.act();
        long t3 = System.nanoTime();
        sim.step();
        long t4 = System.nanoTime();
        robotNs += (t1 - t0) + (t3 - t2);
        engineNs += t2 - t1;
        physicsNs += t4 - t3;
        steps++;
        return t4 - t0;
    }

    /**
     * One control step of each robot of a group, as an engine process serving them all runs it:
     * every robot senses, the engines' iterations run as one {@link IterationBatch} (their tables
     * read in one query, their transactions committed as one), every robot acts and its physics
     * steps. Each robot's step is the same as {@link #step()}'s (the robots share nothing but the
     * database); the batch's read and commit are shared out among the engines' times.
     *
     * @param rigs       the group
     * @param enginePool the engines' database
     */
    static void stepAll(List<Rig> rigs, DataSource enginePool) {
        List<RobotEngine> engines = new ArrayList<>(rigs.size());
        for (Rig rig : rigs) {
            long t0 = System.nanoTime();
            rig.controller.sense();
            rig.robotNs += System.nanoTime() - t0;
            engines.add(rig.engine);
        }
        long t0 = System.nanoTime();
        IterationBatch batch = null;
        try {
            batch = IterationBatch.start(enginePool, engines);
        } catch (SQLException e) {
            rigs.get(0).lastFailure = "read ahead: " + e.getMessage(); // each iteration reads and commits its own
        }
        long shared = System.nanoTime() - t0;
        for (Rig rig : rigs) {
            long t1 = System.nanoTime();
            try {
                rig.engine.iterate();
            } catch (RuntimeException e) {
                rig.failedIterations++;
                rig.lastFailure = e.getMessage();
            }
            rig.engineNs += System.nanoTime() - t1;
        }
        if (batch != null) {
            long t2 = System.nanoTime();
            try {
                batch.commit();
            } catch (SQLException e) {
                for (RobotEngine rolledBack : batch.rolledBack()) { // those whose iteration threw counted it already
                    rigs.get(engines.indexOf(rolledBack)).failedIterations++;
                }
                rigs.get(0).lastFailure = "batch commit: " + e.getMessage();
            } finally {
                batch.close();
            }
            shared += System.nanoTime() - t2;
        }
        for (Rig rig : rigs) {
            rig.engineNs += shared / rigs.size();
            long t2 = System.nanoTime();
            rig.controller.act();
            long t3 = System.nanoTime();
            rig.sim.step();
            rig.robotNs += t3 - t2;
            rig.physicsNs += System.nanoTime() - t3;
            rig.steps++;
        }
    }

    /** Zeroes the per-part times and the step count. */
    void resetTimes() {
        robotNs = 0;
        engineNs = 0;
        physicsNs = 0;
        steps = 0;
    }

    /** Starts a new lap when the engine has marked every checkpoint reached (not part of a step). */
    void rearm() throws SQLException {
        if (laps != null) {
            lapsDone = laps.laps;
            return;
        }
        try (Connection c = rearmPool.getConnection()) {
            try (PreparedStatement ps = c.prepareStatement(
                    "SELECT COUNT(*) FROM checkpoints WHERE robot_id = ? AND reached = FALSE")) {
                ps.setInt(1, robotId);
                try (ResultSet rs = ps.executeQuery()) {
                    rs.next();
                    if (rs.getLong(1) > 0) {
                        return;
                    }
                }
            }
            try (PreparedStatement ps = c.prepareStatement(
                    "UPDATE checkpoints SET reached = FALSE, reached_sim_time_ms = NULL WHERE robot_id = ?")) {
                ps.setInt(1, robotId);
                if (ps.executeUpdate() > 0) {
                    lapsDone++;
                }
            }
        }
    }

    GroundTruth truth() {
        return sim.groundTruth();
    }

    @Override
    public void close() throws Exception {
        controller.close();
        if (owned != null) {
            owned.close();
        }
    }

    /** Rows per table of the whole database (all robots). */
    static Map<String, Long> rowCounts(DataSource pool) throws SQLException {
        Map<String, Long> counts = new LinkedHashMap<>();
        try (Connection c = pool.getConnection(); Statement s = c.createStatement()) {
            for (String table : Schema.tableNames()) {
                try (ResultSet rs = s.executeQuery("SELECT COUNT(*) FROM " + table)) {
                    rs.next();
                    counts.put(table, rs.getLong(1));
                }
            }
        }
        return counts;
    }

    /**
     * The direct link's mission table, looping: the engine's marks are kept here too, and
     * forgotten (a new lap) once every checkpoint is marked.
     */
    static final class Laps implements MissionTables {
        private final MissionTables target;
        private final java.util.Set<Integer> reached = new java.util.HashSet<>();
        long laps;

        Laps(MissionTables target) {
            this.target = target;
        }

        @Override
        public List<Checkpoint> checkpoints() {
            List<Checkpoint> all = target.checkpoints();
            if (!all.isEmpty() && reached.size() >= all.size()) {
                reached.clear();
                laps++;
            }
            return all.stream().map(c -> new Checkpoint(c.seq(), c.xM(), c.yM(), c.radiusM(), reached.contains(c.seq())))
                    .toList();
        }

        @Override
        public void markReached(int seq, long simTimeMs) {
            reached.add(seq);
            target.markReached(seq, simTimeMs);
        }

        @Override
        public Optional<Station> rechargeStation() {
            return target.rechargeStation();
        }

        @Override
        public OptionalDouble rechargeLevelPct() {
            return target.rechargeLevelPct();
        }

        @Override
        public Optional<InitialPose> initialPose() {
            return target.initialPose();
        }
    }
}
