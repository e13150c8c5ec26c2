package org.proactiverobotics.engine.robot;

import java.sql.Connection;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.UnaryOperator;
import javax.sql.DataSource;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.engine.Algorithm;
import org.proactiverobotics.engine.IterationListener;
import org.proactiverobotics.engine.IterationSummary;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.Scenario;
import org.proactiverobotics.engine.ScenarioRegistry;
import org.proactiverobotics.engine.StartUp;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.StateStoreException;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.persistence.CommitGroup;
import org.proactiverobotics.engine.persistence.IterationTransaction;
import org.proactiverobotics.engine.persistence.JdbcStateStore;
import org.proactiverobotics.engine.persistence.StateCodec;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.scenario.battery.BatteryMonitorScenario;
import org.proactiverobotics.engine.scenario.dataacquisition.DataAcquisitionScenario;
import org.proactiverobotics.engine.scenario.decision.DecisionMakingScenario;
import org.proactiverobotics.engine.scenario.decision.DecisionObserver;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.scenario.failsafe.FailSafeScenario;
import org.proactiverobotics.engine.scenario.localisation.LocalisationScenario;
import org.proactiverobotics.engine.scenario.mapping.MappingScenario;
import org.proactiverobotics.engine.scenario.traffic.YieldScenario;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMapTable;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine side of one robot, wired as every caller runs it (the one-process mission, the
 * engine process, tests, benchmarks): the Proactive Engine with the built-in scenarios and any
 * plug-ins in the standard order, the table services, the strategy, a saved state, one
 * transaction per iteration over a database, and the pruning that keeps the engine's history
 * bounded.
 *
 * <p>Start order: {@value #ORDER_TEXT}; in a world shared with other robots ({@link Builder#sharedWorld}):
 * {@value #SHARED_WORLD_ORDER_TEXT}, Yield in slot 3 and the plug-ins after it. Slots: the built-in scenarios that suggest keep the
 * CommandArray slots they always had (ReachDestination 0, BatteryMonitor 1, ObstacleAvoidance 2),
 * so states saved by earlier versions resume; each plug-in gets the next free slot, in the order
 * given; a saved state's slots are kept on a resume.
 *
 * <pre>{@code
 * RobotEngine engine = RobotEngine.builder().robotId(1).database(dataSource)
 *         .drive(new DriveProfile(0.5, 0.24)).plugins(ScenarioPlugins.load(jars, RobotEngine.builtInScenarios()))
 *         .build();
 * engine.startFresh();                       // or resume()
 * engine.writeStrategy(Strategy.named("safety-first"));
 * engine.iterate();                          // once per control step
 * }</pre>
 */
public final class RobotEngine {

    /** Where the plug-ins stand in {@link #startOrder}'s phrase, {@value}. */
    public static final String PLUGINS = "plug-ins";
    /** The start order, for the javadoc and the help texts: {@link #startOrderPhrase()}, which a test keeps it equal to. */
    public static final String ORDER_TEXT = "DataAcquisition → Localisation → Mapping → BatteryMonitor → ReachDestination → plug-ins"
            + " → ObstacleAvoidance → FailSafe → DecisionMaking";
    /** Prune the engine's history every this many iterations (finding the cut-off walks the kept rows: seldom is cheaper). */
    public static final int PRUNE_EVERY = 500;
    /** Keep this many of the robot's newest commands, answered requests and rule failures. */
    public static final int KEEP_ROWS = 1000;

    /**
     * Built-in scenarios with their slots (-1: none), started in this order (the paper's 1 → 4 → 2 → 3,
     * Localisation then Mapping after 1: every later scenario reads this iteration's pose), the plug-ins before
     * ObstacleAvoidance: the collision monitor vets any scenario's command.
     */
    private static final Map<String, Integer> FIRST = orderedMap(
            DataAcquisitionScenario.NAME, -1,
            LocalisationScenario.NAME, -1,
            MappingScenario.NAME, -1,
            BatteryMonitorScenario.NAME, 1,
            ReachDestinationScenario.NAME, 0,
            ObstacleAvoidanceScenario.NAME, 2);
    /**
     * Only in a world shared with other robots ({@link Builder#sharedWorld}): the traffic scenario, with
     * its slot, started right after ReachDestination (so it sees this iteration's route-driven
     * robot) and before the plug-ins and the collision monitor (which vets its backing off).
     */
    private static final Map<String, Integer> SHARED_WORLD = orderedMap(YieldScenario.NAME, 3);
    /** The start order in a world shared with other robots, for the javadoc and the help texts: {@link #startOrderPhrase(boolean)}. */
    public static final String SHARED_WORLD_ORDER_TEXT = "DataAcquisition → Localisation → Mapping → BatteryMonitor → ReachDestination"
            + " → Yield → plug-ins → ObstacleAvoidance → FailSafe → DecisionMaking";
    /** Started after every scenario that suggests: the fail-safe withdraws a failing one's word before the decision reads it. */
    private static final List<String> LAST = List.of(FailSafeScenario.NAME, DecisionMakingScenario.NAME);

    private static final Logger LOG = LoggerFactory.getLogger(RobotEngine.class);

    private final ProactiveEngine engine;
    private final EngineTables tables;
    private final IterationTransaction transaction;
    /** The tables over the database, or null (tables given): what a snapshot is read ahead into. */
    private final JdbcRobotTables jdbcTables;
    private final ScenarioRegistry registry;
    private final List<String> order;
    /** The map as the rules know it: read again from the rows after a start or a resume. */
    private final KnownMap knownMap;
    /** An iteration ran in memory but its transaction did not commit. */
    private boolean aheadOfDatabase;
    /** The committing iteration's number calls for pruning the history once it is in the database. */
    private boolean pruneDue;
    /** What the running iteration commits besides its own writes, or null. */
    private WithCommit withCommit;

    /** Rows that commit with one iteration, in its transaction: a handshake's "served step k". */
    @FunctionalInterface
    public interface WithCommit {
        /**
         * @param writes    the iteration's writes (sent with its commit where the server allows)
         * @param iteration the iteration about to commit
         * @throws SQLException to roll the iteration back
         */
        void write(Writes writes, long iteration) throws SQLException;
    }

    private RobotEngine(ProactiveEngine engine, EngineTables tables, IterationTransaction transaction,
                        JdbcRobotTables jdbcTables, ScenarioRegistry registry, List<String> order, KnownMap knownMap) {
        this.jdbcTables = jdbcTables;
        this.knownMap = knownMap;
        this.engine = engine;
        this.tables = tables;
        this.transaction = transaction;
        this.registry = registry;
        this.order = order;
        if (transaction != null) {
            // also when the group it committed with rolls back after the iteration returned (CommitGroup)
            transaction.onRollback(() -> aheadOfDatabase = true);
            transaction.onCommit(() -> { // after the commit: pruning must not wait on the iteration's own row locks
                if (pruneDue) {
                    pruneDue = false;
                    prune();
                }
            });
            transaction.beforeCommit(() -> {
                if (withCommit != null) {
                    withCommit.write(transaction.writes(), engine.iteration());
                }
            });
        }
    }

    /** @return a builder: robot 1, lazy algorithm, the default drive, no plug-ins */
    public static Builder builder() {
        return new Builder();
    }

    /** @return the names of the built-in scenarios, which a plug-in may not take */
    public static Set<String> builtInScenarios() {
        Set<String> names = new LinkedHashSet<>(FIRST.keySet());
        names.addAll(SHARED_WORLD.keySet());
        names.addAll(LAST);
        return names;
    }

    /**
     * The slots a fresh engine gives, before it starts: what a strategy is checked against
     * before anything runs.
     *
     * @param plugins the plug-ins that will be loaded
     * @return each suggesting scenario's slot on a fresh start, by slot
     */
    public static Map<String, Integer> freshSlots(ScenarioPlugins plugins) {
        return freshSlots(plugins, false);
    }

    /**
     * {@link #freshSlots(ScenarioPlugins)}, in a world shared with other robots or not.
     *
     * @param plugins     the plug-ins that will be loaded
     * @param sharedWorld whether the engine runs the traffic scenario ({@link Builder#sharedWorld})
     * @return each suggesting scenario's slot on a fresh start, by slot
     */
    public static Map<String, Integer> freshSlots(ScenarioPlugins plugins, boolean sharedWorld) {
        Map<String, Integer> slots = new LinkedHashMap<>();
        FIRST.forEach((name, slot) -> {
            if (slot >= 0) {
                slots.put(name, slot);
            }
        });
        if (sharedWorld) {
            slots.putAll(SHARED_WORLD);
        }
        int next = 0;
        for (String name : plugins.scenarios().keySet()) {
            while (slots.containsValue(next)) {
                next++;
            }
            slots.put(name, next);
        }
        Map<String, Integer> bySlot = new LinkedHashMap<>();
        slots.entrySet().stream().sorted(Map.Entry.comparingByValue()).forEach(e -> bySlot.put(e.getKey(), e.getValue()));
        return Collections.unmodifiableMap(bySlot);
    }

    /**
     * The order StartUp starts the scenarios in, the one order every engine uses (the builder
     * takes it from here): the built-in scenarios that find the way, the plug-ins in the order
     * given, then the collision monitor (so that it vets a plug-in's command too), the fail-safe and
     * the decision.
     *
     * @param plugins the plug-ins' scenario names, in the order given
     * @return every scenario's name, in start order
     */
    public static List<String> startOrder(List<String> plugins) {
        return startOrder(plugins, false);
    }

    /**
     * {@link #startOrder(List)}, in a world shared with other robots or not: there the traffic
     * scenario starts right after ReachDestination.
     *
     * @param plugins     the plug-ins' scenario names, in the order given
     * @param sharedWorld whether the engine runs the traffic scenario ({@link Builder#sharedWorld})
     * @return every scenario's name, in start order
     */
    public static List<String> startOrder(List<String> plugins, boolean sharedWorld) {
        List<String> order = new ArrayList<>(FIRST.keySet());
        order.remove(ObstacleAvoidanceScenario.NAME);
        if (sharedWorld) {
            order.addAll(SHARED_WORLD.keySet());
        }
        order.addAll(plugins);
        order.add(ObstacleAvoidanceScenario.NAME);
        order.addAll(LAST);
        return List.copyOf(order);
    }

    /**
     * @return the start order as the documentation and the help texts state it: the scenarios
     *         joined by " → ", the plug-ins standing as {@value #PLUGINS}
     */
    public static String startOrderPhrase() {
        return startOrderPhrase(false);
    }

    /**
     * @param sharedWorld in a world shared with other robots or not
     * @return the start order as the documentation states it ({@link #ORDER_TEXT}, {@link #SHARED_WORLD_ORDER_TEXT})
     */
    public static String startOrderPhrase(boolean sharedWorld) {
        return String.join(" → ", startOrder(List.of(PLUGINS), sharedWorld));
    }

    /** Starts from StartUp, discarding any saved state of this robot's engine. */
    public void startFresh() {
        startFresh(0);
    }

    /**
     * Starts fresh in the middle of a robot's run: iterations go on after the given one, since the
     * robot ignores commands of earlier iterations than one it ran.
     *
     * @param afterIteration the run's last iteration
     */
    public void startFresh(long afterIteration) {
        knownMap.forget();
        engine.startFresh(afterIteration, new StartUp(order));
    }

    /**
     * Resumes from the saved state, or starts from StartUp when there is none.
     *
     * @return whether a saved state was resumed
     */
    public boolean resume() {
        return resume(0);
    }

    /**
     * Resumes in the middle of a robot's run: from the saved state, or, when there is none, fresh
     * with iterations going on after the given one (the robot ignores commands of earlier ones).
     *
     * @param afterIteration the run's last iteration
     * @return whether a saved state was resumed
     */
    public boolean resume(long afterIteration) {
        knownMap.forget();
        engine.start(afterIteration, new StartUp(order));
        return engine.resumed();
    }

    /**
     * Runs one iteration (state saved at its end) and, every {@value #PRUNE_EVERY} iterations,
     * prunes the engine's history. Over a database, all of it is one transaction: the rules'
     * writes and the saved state commit together or not at all (in an {@link IterationBatch}, with
     * the batch's commit: until then the iteration is not in the database).
     *
     * @return the iteration's summary
     * @throws StateStoreException when the state (or the iteration's transaction) cannot be
     *                             saved; nothing of the iteration is then in the database
     */
    public IterationSummary iterate() {
        return iterate(null);
    }

    /**
     * {@link #iterate()}, with rows that commit in the iteration's transaction (over a database),
     * so that they are in the database exactly when the iteration is.
     *
     * @param alsoCommit writes those rows, or null
     * @return the iteration's summary
     * @throws StateStoreException as {@link #iterate()}
     */
    public IterationSummary iterate(WithCommit alsoCommit) {
        withCommit = alsoCommit;
        try {
            return iterateOnce();
        } finally {
            withCommit = null;
        }
    }

    private IterationSummary iterateOnce() {
        IterationSummary summary;
        if (transaction == null) {
            summary = engine.runIteration();
            if (engine.iteration() % PRUNE_EVERY == 0) {
                prune();
            }
        } else {
            if (aheadOfDatabase) {
                resume(); // the last iteration ran in memory but never committed: the database is the truth
                aheadOfDatabase = false;
            }
            transaction.begin();
            try {
                summary = engine.runIteration();
                pruneDue = engine.iteration() % PRUNE_EVERY == 0; // done once committed (onCommit)
                transaction.commit();
            } catch (SQLException e) {
                transaction.rollback(); // its listener marks the engine ahead of the database
                throw new StateStoreException("committing iteration " + engine.iteration() + " of robot "
                        + engine.robotId() + ": " + e.getMessage(), e);
            } catch (RuntimeException e) {
                transaction.rollback();
                throw e;
            }
        }
        return summary;
    }

    /**
     * Reads the next iteration's tables of several robots' engines in one query, for an engine
     * process that runs their iterations one after the other ({@link IterationBatch}): each then
     * takes up its snapshot at its first read instead of reading its own. Only for robots whose
     * rows nothing but the robot writes until their iteration (see {@link JdbcRobotTables#readAhead});
     * call {@link #dropReadAhead()} on each after their iterations. Engines given tables instead of
     * a database are left out, and nothing is read ahead on H2.
     *
     * @param dataSource the database the engines were built over
     * @param engines    the engines whose iteration comes next
     * @return whether their snapshots were read (not on H2)
     * @throws SQLException when the read fails (nothing is kept: each iteration reads its own)
     */
    static boolean readAhead(DataSource dataSource, List<RobotEngine> engines) throws SQLException {
        List<JdbcRobotTables> tables = new ArrayList<>(engines.size());
        for (RobotEngine e : engines) {
            if (e.jdbcTables != null) {
                tables.add(e.jdbcTables);
            }
        }
        if (tables.isEmpty()) {
            return false;
        }
        try (Connection c = dataSource.getConnection()) {
            return JdbcRobotTables.readAhead(c, tables);
        }
    }

    /** Forgets a snapshot read ahead ({@link #readAhead}) that this engine's iteration did not take up. */
    void dropReadAhead() {
        if (jdbcTables != null) {
            jdbcTables.dropReadAhead();
        }
    }

    /** @return the iterations' transaction, or null (tables given instead of a database) */
    IterationTransaction transaction() {
        return transaction;
    }

    /** The next iteration commits with the group's others (over a database; else it has nothing to commit). */
    void join(CommitGroup group) {
        if (transaction != null) {
            group.add(transaction);
        }
    }

    /** Housekeeping after the iteration, in its own transactions: a failure here costs the iteration nothing. */
    private void prune() {
        try {
            tables.pruneHistory().applyAsInt(KEEP_ROWS);
        } catch (RuntimeException e) {
            LOG.warn("robot {}: pruning the engine's history failed (will try again in {} iterations): {}",
                    engine.robotId(), PRUNE_EVERY, e.getMessage());
        }
    }

    /**
     * Writes a strategy to the robot's strategy table, in the slots the engine gave (start the
     * engine first); the next iteration obeys it.
     *
     * @param strategy the strategy
     * @return the scenarios that suggest but that the strategy leaves out (they rank below every listed one)
     * @throws StrategyException when the strategy names a scenario that is not loaded or does not suggest
     */
    public List<String> writeStrategy(Strategy strategy) {
        Map<String, Integer> slots = slots();
        tables.strategy().write(strategy.rows(slots));
        return strategy.unlisted(slots);
    }

    /**
     * Writes the strategy when the table holds none; else keeps the one there (a strategy changed
     * while the robot ran survives a restart), rewritten by scenario name when it does not match
     * the slots the engine gave (a plug-in added since ranks below the others).
     *
     * @param strategy written when none is set
     * @return true when the given strategy was written
     */
    public boolean ensureStrategy(Strategy strategy) {
        List<StrategyTable.Entry> rows = tables.strategy().read();
        if (rows.isEmpty()) {
            writeStrategy(strategy);
            return true;
        }
        Map<String, Integer> slots = slots();
        boolean matches = rows.size() == slots.size()
                && rows.stream().allMatch(e -> Objects.equals(slots.get(e.scenario()), e.slot()));
        if (!matches) {
            Strategy kept = Strategy.of(rows.stream().filter(e -> slots.containsKey(e.scenario())).toList());
            tables.strategy().write(kept.rows(slots));
            LOG.info("robot {}: strategy rows rewritten for the scenarios' slots {}", engine.robotId(), slots);
        }
        return false;
    }

    /** @return each suggesting scenario's CommandArray slot (after a start) */
    public Map<String, Integer> slots() {
        return engine.memory().slots();
    }

    /** @return the scenarios StartUp starts, in order */
    public List<String> scenarios() {
        return order;
    }

    /** @return every scenario known by name (built-in and plug-ins) */
    public ScenarioRegistry registry() {
        return registry;
    }

    /** @return the engine */
    public ProactiveEngine engine() {
        return engine;
    }

    /** @return what the engine's rules read and write, whatever the layer */
    public EngineTables tables() {
        return tables;
    }

    @SafeVarargs
    private static <V> Map<String, V> orderedMap(Object... keysAndValues) {
        Map<String, V> map = new LinkedHashMap<>();
        for (int i = 0; i < keysAndValues.length; i += 2) {
            @SuppressWarnings("unchecked")
            V value = (V) keysAndValues[i + 1];
            map.put((String) keysAndValues[i], value);
        }
        return Collections.unmodifiableMap(map);
    }

    /** The layer's map rows when its mission tables have them, else a map kept in memory. */
    private static OccupancyMapTable mapTable(EngineTables base) {
        return base.mission() instanceof OccupancyMapTable map ? map : OccupancyMapTable.inMemory();
    }

    /** Configures a {@link RobotEngine}; every setting but the tables has a default. */
    public static final class Builder {
        private int robotId = 1;
        private Algorithm algorithm = Algorithm.LAZY;
        private DriveProfile drive = new DriveProfile(0.5, 0.24);
        private DataSource dataSource;
        private EngineTables tables;
        private StateStore store;
        private UnaryOperator<EngineTables> decorate = UnaryOperator.identity();
        private ScenarioPlugins plugins = ScenarioPlugins.none();
        private DecisionObserver observer;
        private BeliefObserver belief;
        private Set<String> only;
        private final List<IterationListener> listeners = new ArrayList<>();
        private CommitGuard guard;
        private boolean sharedWorld;

        private Builder() {
        }

        /** @param robotId the robot, the {@code robot_id} of the engine's tables and state */
        public Builder robotId(int robotId) {
            this.robotId = robotId;
            return this;
        }

        /**
         * @param sharedWorld whether the robot shares its world with other robots (a fleet world):
         *                    then the engine runs the traffic scenario (Yield, in its own slot) and
         *                    gives the rules the {@link SharedWorld} service, so the map lets cells
         *                    that a robot occupied go free again; false (the default) is the lone
         *                    robot, exactly as before
         */
        public Builder sharedWorld(boolean sharedWorld) {
            this.sharedWorld = sharedWorld;
            return this;
        }

        /** @param algorithm lazy (the default) or standard data acquisition */
        public Builder algorithm(Algorithm algorithm) {
            this.algorithm = Objects.requireNonNull(algorithm);
            return this;
        }

        /** @param drive the robot's drive as the engine assumes it (maximum wheel speed m/s, axle width m) */
        public Builder drive(DriveProfile drive) {
            this.drive = Objects.requireNonNull(drive);
            return this;
        }

        /**
         * Over a shared database (schema applied): the robot's tables, the saved state, and one
         * transaction per iteration.
         *
         * @param dataSource the database
         */
        public Builder database(DataSource dataSource) {
            this.dataSource = Objects.requireNonNull(dataSource);
            this.tables = null;
            return this;
        }

        /**
         * Over any communication layer (an in-process link, a wrapped one in a test).
         *
         * @param tables what the rules read and write
         * @param store  where the state is saved ({@link StateStore#none()}: nowhere)
         */
        public Builder tables(EngineTables tables, StateStore store) {
            this.tables = Objects.requireNonNull(tables);
            this.store = Objects.requireNonNull(store);
            this.dataSource = null;
            return this;
        }

        /** @param decorate wraps the tables the rules see (fault injection in a test, a counter in a benchmark) */
        public Builder decorate(UnaryOperator<EngineTables> decorate) {
            this.decorate = Objects.requireNonNull(decorate);
            return this;
        }

        /** @param plugins scenarios from outside, started as {@link #startOrder} places them: before ObstacleAvoidance */
        public Builder plugins(ScenarioPlugins plugins) {
            this.plugins = Objects.requireNonNull(plugins);
            return this;
        }

        /**
         * Starts only these scenarios (built-in or plug-ins), still in the standard order: a test
         * of one scenario alone. Slots are given as usual, so a scenario suggests into its own.
         *
         * @param scenarios the names of the scenarios to start
         */
        public Builder only(String... scenarios) {
            this.only = new LinkedHashSet<>(List.of(scenarios));
            return this;
        }

        /**
         * Over a database: a check run in every iteration's transaction before anything else
         * of it is written; when it throws, the iteration rolls back (an engine that lost its
         * robot's lease to another engine commits nothing).
         *
         * @param guard the check
         */
        public Builder guard(CommitGuard guard) {
            this.guard = Objects.requireNonNull(guard);
            return this;
        }

        /** @param observer told of every decision (a trace), or null */
        public Builder observer(DecisionObserver observer) {
            this.observer = observer;
            return this;
        }

        /** @param belief told what the scenarios believed in each iteration (a trace), or null */
        public Builder belief(BeliefObserver belief) {
            this.belief = belief;
            return this;
        }

        /** @param listener observes every iteration and rule */
        public Builder listener(IterationListener listener) {
            listeners.add(Objects.requireNonNull(listener));
            return this;
        }

        /**
         * @return the engine side, not started: call {@link #startFresh()} or {@link #resume()}
         * @throws IllegalStateException when neither a database nor tables were given
         */
        public RobotEngine build() {
            IterationTransaction transaction = null;
            EngineTables base = tables;
            JdbcRobotTables jdbcTables = null;
            StateStore stateStore = store;
            StateCodec codec = new StateCodec(plugins.classLoader());
            long[] iteration = {0}; // the guard is told the iteration about to commit
            if (dataSource != null) {
                transaction = new IterationTransaction(dataSource);
                if (guard != null) {
                    CommitGuard check = guard;
                    IterationTransaction tx = transaction;
                    // in the transaction, so that the check's row lock holds until the iteration commits
                    tx.beforeCommit(() -> check.check(tx.connection(), iteration[0]));
                }
                jdbcTables = new JdbcRobotTables(transaction, robotId);
                base = EngineTables.of(jdbcTables);
                stateStore = new JdbcStateStore(transaction, codec);
            } else if (base == null) {
                throw new IllegalStateException("give the engine a database or tables");
            }
            EngineTables wired = decorate.apply(base);

            List<Scenario> known = new ArrayList<>();
            ScenarioRegistry onClassPath = ScenarioRegistry.load(RobotEngine.class.getClassLoader());
            // A plug-in also listed on the class path (a user's own project under test) is taken once, as the plug-in.
            onClassPath.names().stream().filter(name -> !plugins.scenarios().containsKey(name))
                    .forEach(name -> known.add(onClassPath.get(name)));
            known.addAll(plugins.scenarios().values());
            ScenarioRegistry registry = ScenarioRegistry.of(known);

            List<String> order = new ArrayList<>(startOrder(List.copyOf(plugins.scenarios().keySet()), sharedWorld));
            if (only != null) {
                only.forEach(registry::get); // an unknown name fails here, naming the known ones
                order.retainAll(only);
            }

            OccupancyMapTable mapTable = mapTable(base);
            KnownMap knownMap = new KnownMap(mapTable);
            if (transaction != null) {
                transaction.onRollback(knownMap::forget); // chunks of an iteration that did not commit are not in the table
            }
            ProactiveEngine.Builder b = ProactiveEngine.builder()
                    .robotId(robotId)
                    .algorithm(algorithm)
                    .store(stateStore)
                    .service(ScenarioRegistry.class, registry)
                    .service(SensorReadings.class, wired.readings())
                    .service(SensorRequests.class, wired.requests())
                    .service(MissionTables.class, wired.mission())
                    .service(StrategyTable.class, wired.strategy())
                    .service(EngineComments.class, wired.comments())
                    .service(OccupancyMapTable.class, knownMap.table())
                    .service(KnownMap.class, knownMap)
                    .service(PoseEstimateTable.class, wired.poses())
                    .service(DriveProfile.class, drive);
            if (sharedWorld) {
                b.service(SharedWorld.class, SharedWorld.DEFAULT);
            }
            freshSlots(plugins, sharedWorld).forEach(b::slot); // in slot order; a saved state's slots still win on a resume
            if (observer != null) {
                b.service(DecisionObserver.class, observer);
            }
            if (belief != null) {
                b.service(BeliefObserver.class, belief);
            }
            listeners.forEach(b::listener);
            if (stateStore == null) {
                throw new IllegalStateException("give the engine a state store with its tables");
            }
            if (guard != null) {
                b.listener(new IterationListener() {
                    @Override
                    public void iterationStarted(long n, int queued) {
                        iteration[0] = n;
                    }
                });
            }
            return new RobotEngine(b.build(), wired, transaction, jdbcTables, registry, List.copyOf(order), knownMap);
        }
    }
}
