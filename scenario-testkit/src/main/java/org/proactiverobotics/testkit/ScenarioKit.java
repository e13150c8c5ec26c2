package org.proactiverobotics.testkit;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.function.UnaryOperator;
import javax.sql.DataSource;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleFailure;
import org.proactiverobotics.engine.Scenario;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.scenario.dataacquisition.DataAcquisitionScenario;
import org.proactiverobotics.engine.scenario.decision.DecisionMakingScenario;
import org.proactiverobotics.engine.scenario.failsafe.FailSafeScenario;
import org.proactiverobotics.engine.scenario.localisation.LocalisationScenario;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.PoseEstimate;

/**
 * Tests a proactive scenario alone, or a few together: the real engine, wired as a mission
 * wires it ({@link RobotEngine}), over a fresh embedded H2 database with the real schema, and
 * the robot's half scripted step by step. The DecisionMaking scenario always runs, so what a
 * scenario suggests is weighed by a strategy and sent as a real mission would.
 *
 * <pre>{@code
 * try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).start()) {
 *     kit.robot().gps(0, 0).headingDeg(90).scan(1, 1, 1, 0.3, 0.3, 1, 1, 1);
 *     kit.step();
 *     assertThat(kit.suggestion("SpeedGovernor")).isEqualTo("FORWARD 0.1");
 * }
 * }</pre>
 *
 * <p>Time: a step is one control step of {@link Builder#timeStepMs} simulated milliseconds (32
 * by default); the first step is at simulated time 0. One step is one engine iteration.
 *
 * <p>Not thread-safe: one test, one thread.
 */
public final class ScenarioKit implements AutoCloseable {

    /** The robot every kit plays: the {@code robot_id} of its rows. */
    public static final int ROBOT_ID = 1;
    /** A step's length unless set, simulated milliseconds: the robot's default control step. */
    public static final long DEFAULT_TIME_STEP_MS = 32;
    /** Iterations {@link Builder#start()} runs: StartUp, then the scenarios' meta-rules. */
    public static final int START_UP_ITERATIONS = 2;
    /** The name of the strategy the kit writes when none is given. */
    public static final String DEFAULT_STRATEGY_NAME = "testkit";

    private final KitDatabase db;
    private final RobotEngine engine;
    private final long timeStepMs;
    private final ScriptedRobot robot;
    private final Mission mission;

    private final List<Decision> decisions = new ArrayList<>();
    /** Per step since start: the live suggestions by scenario, as the decision saw them. */
    private final List<Map<String, String>> suggestionsByStep = new ArrayList<>();
    /** The decision of the step running or last run; null when it had none. */
    private Decision stepDecision;
    private long simTimeMs;
    private boolean closed;

    private ScenarioKit(Builder b) {
        this.db = b.dataSource == null ? KitDatabase.embeddedH2() : KitDatabase.given(b.dataSource);
        this.timeStepMs = b.timeStepMs;
        this.robot = new ScriptedRobot(ROBOT_ID, db);
        this.mission = new Mission(ROBOT_ID, db);
        try {
            ScenarioPlugins plugins = ScenarioPlugins.of(b.scenarios.toArray(Scenario[]::new));
            Set<String> names = new LinkedHashSet<>(b.builtIns);
            names.addAll(plugins.scenarios().keySet());
            names.add(LocalisationScenario.NAME); // the pose every scenario reads: the fix and heading as given, or filtered odometry
            names.add(DecisionMakingScenario.NAME);
            this.engine = RobotEngine.builder()
                    .robotId(ROBOT_ID)
                    .database(db.dataSource())
                    .plugins(plugins)
                    .sharedWorld(b.sharedWorld)
                    .only(names.toArray(String[]::new))
                    .decorate(b.faults)
                    .observer(this::decided)
                    .build();
            engine.startFresh();
            Strategy strategy = b.strategy != null ? b.strategy : defaultStrategy(plugins);
            engine.writeStrategy(b.sharedWorld && b.strategy == null ? strategy.forSharedWorld() : strategy);
            for (int i = 0; i < START_UP_ITERATIONS; i++) {
                engine.iterate();
            }
        } catch (RuntimeException e) {
            db.close();
            throw e;
        }
    }

    /** @return a builder: no scenario yet, 32 ms steps, a fresh embedded H2 database */
    public static Builder builder() {
        return new Builder();
    }

    /** The given scenarios above the built-in ones (the first given highest), the built-ins as safety-first ranks them. */
    private static Strategy defaultStrategy(ScenarioPlugins plugins) {
        Strategy safetyFirst = Strategy.named(Strategy.SAFETY_FIRST);
        if (plugins.scenarios().isEmpty()) {
            return safetyFirst;
        }
        int top = safetyFirst.priorities().values().stream().mapToInt(Integer::intValue).max().orElse(0);
        Map<String, Integer> priorities = new LinkedHashMap<>();
        int rank = top + plugins.scenarios().size();
        for (String name : plugins.scenarios().keySet()) {
            priorities.put(name, rank--);
        }
        priorities.putAll(safetyFirst.priorities());
        return new Strategy(DEFAULT_STRATEGY_NAME, priorities, Map.of());
    }

    private void decided(long iteration, CommandArray commands, Suggestion winner) {
        stepDecision = new Decision(iteration, live(commands), winner.scenario(), winner.command());
    }

    private static Map<String, String> live(CommandArray commands) {
        Map<String, String> seen = new LinkedHashMap<>();
        for (int slot = 0; slot < commands.size(); slot++) {
            Suggestion s = commands.get(slot);
            if (s != null) {
                seen.put(s.scenario(), s.command());
            }
        }
        return seen;
    }

    // ------------------------------------------------------------------ the script

    /** @return the robot: set what its sensors read from the next step on */
    public ScriptedRobot robot() {
        return robot;
    }

    /** @return the mission rows (checkpoints, the station), written at once */
    public Mission mission() {
        return mission;
    }

    /**
     * One control step: the robot writes its readings at this step's simulated time and answers
     * the pending requests of the sensors that publish; the engine runs one iteration; the
     * simulated time moves on by the time step.
     *
     * @return this kit
     * @throws ScenarioKitException when the kit is closed or its database refuses a reading
     */
    public ScenarioKit step() {
        if (closed) {
            throw new ScenarioKitException("the kit is closed");
        }
        robot.publish(simTimeMs);
        stepDecision = null;
        engine.iterate();
        if (stepDecision != null) {
            decisions.add(stepDecision);
            suggestionsByStep.add(stepDecision.suggestions());
        } else {
            // no decision this iteration (its scenario failed): the CommandArray as the iteration left it
            suggestionsByStep.add(Collections.unmodifiableMap(live(engine.engine().memory().commandArray())));
        }
        simTimeMs += timeStepMs;
        return this;
    }

    /**
     * @param steps how many control steps to run
     * @return this kit
     */
    public ScenarioKit step(int steps) {
        for (int i = 0; i < steps; i++) {
            step();
        }
        return this;
    }

    // ------------------------------------------------------------------ what happened

    /**
     * @param scenario a running scenario's name
     * @return its live suggestion in the last step (the command, e.g. {@code FORWARD 0.1}), or
     *         null when it suggested nothing
     * @throws IllegalArgumentException when no running scenario of that name suggests
     */
    public String suggestion(String scenario) {
        checkSuggests(scenario);
        return suggestionsByStep.isEmpty() ? null : suggestionsByStep.get(suggestionsByStep.size() - 1).get(scenario);
    }

    /**
     * @param scenario a running scenario's name
     * @return its live suggestion in each step since start, oldest first; null for a step where
     *         it suggested nothing
     * @throws IllegalArgumentException when no running scenario of that name suggests
     */
    public List<String> suggestions(String scenario) {
        checkSuggests(scenario);
        List<String> out = new ArrayList<>(suggestionsByStep.size());
        suggestionsByStep.forEach(s -> out.add(s.get(scenario)));
        return Collections.unmodifiableList(out);
    }

    private void checkSuggests(String scenario) {
        if (!engine.slots().containsKey(scenario)) {
            throw new IllegalArgumentException("no scenario '" + scenario + "' suggests here; those that can: "
                    + String.join(", ", engine.slots().keySet()));
        }
    }

    /** @return the decision of the last step, or null when none ran (no step yet, or its scenario failed) */
    public Decision decision() {
        return stepDecision;
    }

    /** @return every decision since start, oldest first */
    public List<Decision> decisions() {
        return Collections.unmodifiableList(decisions);
    }

    /** @return the commands sent to the robot since start, oldest first ({@code engine_comments}) */
    public List<String> sentCommands() {
        return sent().stream().map(SentCommand::command).toList();
    }

    /** @return the commands sent to the robot since start, with who and when, oldest first */
    public List<SentCommand> sent() {
        return db.query("SELECT iteration, sim_time_ms, scenario, command FROM engine_comments WHERE robot_id = ? ORDER BY id",
                rs -> new SentCommand(rs.getLong(1), rs.getLong(2), rs.getString(3), rs.getString(4)), ROBOT_ID);
    }

    /**
     * @return the sensors of the requests the engine wrote that the robot has not answered yet,
     *         oldest first ({@code GPS}, {@code IU}, {@code DS}, {@code BATTERY}, {@code ODOMETRY})
     */
    public List<String> requestedSensors() {
        return db.query("SELECT sensor FROM sensor_requests WHERE robot_id = ? AND answered_sim_time_ms IS NULL ORDER BY id",
                rs -> rs.getString(1), ROBOT_ID);
    }

    /** @return the rules queued for the next step, in run order, as {@code Scenario/Rule} */
    public List<String> scheduled() {
        return engine.engine().nextQueue().stream().map(Rule::toString).toList();
    }

    /** @return the failures of the rule parts that threw in the last step */
    public List<RuleFailure> failures() {
        return engine.engine().lastIterationFailures();
    }

    /** @return the sequence numbers of the checkpoints marked reached, in order */
    public List<Integer> reachedCheckpoints() {
        return db.query("SELECT seq FROM checkpoints WHERE robot_id = ? AND reached = TRUE ORDER BY seq",
                rs -> rs.getInt(1), ROBOT_ID);
    }

    /**
     * @return the engine's newest pose estimate ({@code pose_estimate}, the Localisation scenario's):
     *         the fix and heading as scripted when the robot reports no odometry, else the filter's
     */
    public Optional<PoseEstimate> pose() {
        return engine.tables().poses().newestPose();
    }

    /** @return the memory the scenarios share: CommandArray, PriorityArray, named values */
    public SharedMemory memory() {
        return engine.engine().memory();
    }

    /** @return the simulated time the next step writes its readings at, milliseconds (0 before the first) */
    public long simTimeMs() {
        return simTimeMs;
    }

    /** @return the engine side under test (its engine, tables, slots; {@code writeStrategy} to change the strategy) */
    public RobotEngine engine() {
        return engine;
    }

    /** @return the database the kit runs on (for a query of your own, or a second engine) */
    public DataSource database() {
        return db.dataSource();
    }

    /** Drops the embedded database the kit made; a database given to the builder is left as it is. */
    @Override
    public void close() {
        closed = true;
        db.close();
    }

    /** Chooses the scenarios, the strategy, the time step and the database of a {@link ScenarioKit}. */
    public static final class Builder {
        private final List<Scenario> scenarios = new ArrayList<>();
        private final Set<String> builtIns = new LinkedHashSet<>();
        private Strategy strategy;
        private long timeStepMs = DEFAULT_TIME_STEP_MS;
        private DataSource dataSource;
        private UnaryOperator<EngineTables> faults = UnaryOperator.identity();
        private boolean sharedWorld;

        private Builder() {
        }

        /**
         * The robot shares its world with other robots, as in a fleet world's run: the map lets
         * cells go free again when rays see through them, {@code Yield} may be run
         * ({@code builtIn("Yield")}), and the default strategy ranks it right below ObstacleAvoidance
         * ({@link Strategy#forSharedWorld()}).
         *
         * @return this builder
         */
        public Builder sharedWorld() {
            this.sharedWorld = true;
            return this;
        }

        /**
         * @param scenario a scenario of yours, run as a plug-in is (its slot given by the engine);
         *                 several start in the order given, where {@link RobotEngine#startOrder} puts plug-ins
         * @return this builder
         */
        public Builder scenario(Scenario scenario) {
            scenarios.add(Objects.requireNonNull(scenario, "scenario"));
            return this;
        }

        /**
         * @param names built-in scenarios to run too: {@code DataAcquisition}, {@code BatteryMonitor},
         *              {@code ReachDestination}, {@code ObstacleAvoidance}, {@code FailSafe}
         *              ({@code DecisionMaking} always runs); they start in the standard order
         * @return this builder
         * @throws IllegalArgumentException for a name that is not a built-in scenario
         */
        public Builder builtIn(String... names) {
            Set<String> known = RobotEngine.builtInScenarios();
            for (String name : names) {
                if (!known.contains(name)) {
                    throw new IllegalArgumentException("no built-in scenario '" + name + "'; built-in: " + String.join(", ", known));
                }
                builtIns.add(name);
            }
            return this;
        }

        /** @return this builder, with the DataAcquisition scenario, which requests sensor readings */
        public Builder withDataAcquisition() {
            return builtIn(DataAcquisitionScenario.NAME);
        }

        /** @return this builder, with the FailSafe scenario, which withdraws and restarts failing scenarios */
        public Builder withFailSafe() {
            return builtIn(FailSafeScenario.NAME);
        }

        /**
         * @param strategy the strategy the decision obeys; by default your scenarios rank above
         *                 the built-in ones (the first given highest), which rank as in {@code safety-first}
         * @return this builder
         */
        public Builder strategy(Strategy strategy) {
            this.strategy = Objects.requireNonNull(strategy, "strategy");
            return this;
        }

        /**
         * @param json a strategy as a strategy file holds it:
         *             {@code {"priorities": {"<scenario>": <int>, ...}, "timeoutsMs": {...}}}
         * @return this builder
         * @throws org.proactiverobotics.engine.robot.StrategyException naming the key when the JSON is not a strategy
         */
        public Builder strategyJson(String json) {
            return strategy(Strategy.parse(json, "strategyJson"));
        }

        /**
         * @param timeStepMs simulated milliseconds between two steps (32 by default), at least 1
         * @return this builder
         */
        public Builder timeStepMs(long timeStepMs) {
            if (timeStepMs < 1) {
                throw new IllegalArgumentException("time step must be at least 1 ms: " + timeStepMs);
            }
            this.timeStepMs = timeStepMs;
            return this;
        }

        /**
         * @param dataSource runs on this database instead of a fresh embedded H2 (MariaDB, say);
         *                   the schema is applied where a table is missing; it should hold no rows
         *                   of robot {@value ScenarioKit#ROBOT_ID}; the kit does not close it
         * @return this builder
         */
        public Builder database(DataSource dataSource) {
            this.dataSource = Objects.requireNonNull(dataSource, "dataSource");
            return this;
        }

        /**
         * @param faults wraps the tables the rules see, to inject faults (a table that throws for
         *               one scenario, say)
         * @return this builder
         */
        public Builder faults(UnaryOperator<EngineTables> faults) {
            this.faults = Objects.requireNonNull(faults, "faults");
            return this;
        }

        /**
         * Starts a fresh engine with the chosen scenarios, writes the strategy, and runs the
         * {@value ScenarioKit#START_UP_ITERATIONS} start-up iterations: the next {@link ScenarioKit#step()}
         * is the first in which the scenarios' own rules run.
         *
         * @return the kit; close it at the end of the test
         * @throws IllegalArgumentException or {@link org.proactiverobotics.engine.robot.PluginException}
         *         for a scenario with a bad or taken name, {@link org.proactiverobotics.engine.robot.StrategyException}
         *         for a strategy that names a scenario that is not there
         */
        public ScenarioKit start() {
            return new ScenarioKit(this);
        }
    }
}
