package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.JdbcStateStore;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.RuleFailure;
import org.proactiverobotics.engine.ScenarioRegistry;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.scenario.battery.BatteryMonitorScenario;
import org.proactiverobotics.engine.scenario.dataacquisition.DataAcquisitionScenario;
import org.proactiverobotics.engine.scenario.decision.DecisionMakingScenario;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.scenario.failsafe.FailSafeScenario;
import org.proactiverobotics.engine.scenario.failsafe.WatchFailures;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * The fail-safe scenario with the five robot scenarios: a rule that throws, in each scenario in
 * turn, while the robot sits before an obstacle on its way to a checkpoint.
 */
class FailSafeScenarioTest {

    static final String[] ORDER = {"DataAcquisition", "BatteryMonitor", "ReachDestination", "ObstacleAvoidance",
            FailSafeScenario.NAME, "DecisionMaking"};
    private static final double FREE = 1.0;

    private long t;

    static Stream<Arguments> scenarios() {
        return Stream.of(
                Arguments.of(DataAcquisitionScenario.NAME, DataAcquisitionScenario.class),
                Arguments.of(BatteryMonitorScenario.NAME, BatteryMonitorScenario.class),
                Arguments.of(ReachDestinationScenario.NAME, ReachDestinationScenario.class),
                Arguments.of(ObstacleAvoidanceScenario.NAME, ObstacleAvoidanceScenario.class),
                Arguments.of(DecisionMakingScenario.NAME, DecisionMakingScenario.class));
    }

    private RobotTablesFixture mission() throws Exception {
        RobotTablesFixture f = new RobotTablesFixture(ORDER);
        f.tables.write(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots()));
        f.checkpoint(0, 0.0, 3.0);
        f.station(-3.0, 0.0, 100.0);
        return f;
    }

    /** One control step of a robot at the origin facing the checkpoint, an obstacle 0.2 m ahead. */
    private List<RuleFailure> step(RobotTablesFixture f) throws Exception {
        t += 32;
        f.gps(t, 0.0, 0.0);
        f.heading(t, Math.PI / 2);
        f.scan(t, FREE, FREE, 0.25, 0.2, 0.2, 0.25, FREE, FREE);
        f.battery(t, 90.0, false);
        f.answerAll(t);
        f.engine.runIteration();
        return f.engine.lastIterationFailures();
    }

    private static Set<String> queuedScenarios(RobotTablesFixture f) {
        return f.engine.nextQueue().stream().map(Rule::scenario).collect(Collectors.toSet());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenarios")
    void aRuleThatThrowsIsContainedTheOthersGoOnAndTheScenarioComesBack(String failing, Class<?> scenarioClass)
            throws Exception {
        try (RobotTablesFixture f = mission()) {
            for (int i = 0; i < 6; i++) {
                assertThat(step(f)).isEmpty();
            }
            assertThat(f.decisions).last().extracting(RobotTablesFixture.Decision::winner).isEqualTo("ObstacleAvoidance");
            long failAt = f.engine.iteration() + 1;
            long lastSentBefore = f.sent().get(f.sent().size() - 1).id();
            int decisionsBefore = f.decisions.size();

            f.faulty.fail(scenarioClass);
            List<RuleFailure> failures = new ArrayList<>();
            for (int i = 0; i < 8; i++) {
                failures.addAll(step(f));
            }
            // The iteration goes on: only the failing scenario failed, every other one still runs.
            assertThat(failures).isNotEmpty().allSatisfy(x -> assertThat(x.scenario()).isEqualTo(failing));
            assertThat(queuedScenarios(f)).containsAll(Stream.of(ORDER).filter(s -> !s.equals(failing)).toList());
            // No decision after the failure saw a suggestion of the failing scenario ...
            assertThat(f.decisions.subList(decisionsBefore, f.decisions.size()))
                    .allSatisfy(d -> assertThat(d.suggestions()).doesNotContainKey(failing));
            // ... and no command of it was sent, not even the one decided just before it failed.
            List<RobotTablesFixture.Sent> after = f.sent().stream().filter(s -> s.id() > lastSentBefore).toList();
            assertThat(after).isNotEmpty().noneSatisfy(s -> assertThat(s.scenario()).isEqualTo(failing));
            // The robot is safe: it stops, or avoids the obstacle (when avoidance itself is healthy).
            assertThat(after).allSatisfy(s -> assertThat(s.command().equals("STOP")
                    || s.scenario().equals("ObstacleAvoidance")).as(s.toString()).isTrue());
            if (!failing.equals("BatteryMonitor") && !failing.equals("ReachDestination")) {
                // Avoidance gone: its slot holds STOP; data or decision gone: STOP, straight to the robot.
                assertThat(after.get(after.size() - 1).command()).isEqualTo("STOP");
            }
            // The decision runs after the fail-safe: its failure is met an iteration later.
            long goneAt = failing.equals("DecisionMaking") ? failAt + 1 : failAt;
            assertThat(f.engine.memory().values().get(WatchFailures.RECORD_PREFIX + failing))
                    .startsWith("gone at iteration " + goneAt);

            f.faulty.heal();
            for (int i = 0; i < (int) WatchFailures.RESTART_AFTER_ITERATIONS + 4; i++) {
                assertThat(step(f)).isEmpty();
            }
            assertThat(f.engine.memory().values().get(WatchFailures.RECORD_PREFIX + failing)).startsWith("back after 1 restart(s)");
            assertThat(queuedScenarios(f)).contains(failing);
            List<Rule> queue = f.engine.nextQueue();
            assertThat(queue.get(queue.size() - 1).name()).as("the decision still runs last").isEqualTo("ReadRobotCommands");
            assertThat(f.decisions).last().extracting(RobotTablesFixture.Decision::winner).isEqualTo("ObstacleAvoidance");
            assertThat(f.sent()).last().extracting(RobotTablesFixture.Sent::scenario).isEqualTo("ObstacleAvoidance");
        }
    }

    @Test
    void aDataAcquisitionRuleLostToOneFaultIsRestoredSoItsSensorKeepsBeingRead() throws Exception {
        try (RobotTablesFixture f = mission()) {
            for (int i = 0; i < 4; i++) {
                step(f);
            }
            f.faulty.failOnce(org.proactiverobotics.engine.tables.Sensor.DS);
            List<RuleFailure> failures = step(f);
            assertThat(failures).singleElement().satisfies(x -> assertThat(x.rule()).isEqualTo("GetDS"));
            step(f);
            assertThat(f.engine.nextQueue()).extracting(Rule::name).contains("GetDS");
            f.answerAll(t); // nothing pending is left unanswered ...
            step(f);
            assertThat(f.pendingSensors()).as("... and the scan is asked for again").contains("DS");
            assertThat(f.engine.memory().values().get(WatchFailures.RECORD_PREFIX + "DataAcquisition"))
                    .startsWith("running again with 1 lost rule(s) restored");
        }
    }

    @Test
    void deadObstacleAvoidanceUnderSafetyFirstStopsTheRobotUntilItIsBack() throws Exception {
        try (RobotTablesFixture f = mission()) {
            for (int i = 0; i < 6; i++) {
                step(f);
            }
            long lastSentBefore = f.sent().get(f.sent().size() - 1).id();
            f.faulty.fail(ObstacleAvoidanceScenario.class);
            step(f);
            f.faulty.heal();
            for (int i = 0; i < WatchFailures.RESTART_AFTER_ITERATIONS; i++) {
                step(f);
            }
            // One STOP withdrawn-and-replaced by the decision, then the fail-safe's STOP until the restart.
            step(f); // the meta-rule runs: STOP still stands in
            step(f); // AvoidObstacles runs again and wins the decision ...
            step(f); // ... whose command is sent now
            List<RobotTablesFixture.Sent> after = f.sent().stream().filter(s -> s.id() > lastSentBefore).toList();
            // The command decided before the failure is withdrawn for a STOP, then the fail-safe's STOP
            // until avoidance is back.
            assertThat(after.get(0)).extracting(RobotTablesFixture.Sent::scenario, RobotTablesFixture.Sent::command)
                    .containsExactly("DecisionMaking", "STOP");
            assertThat(after.subList(1, after.size() - 1)).hasSize((int) WatchFailures.RESTART_AFTER_ITERATIONS + 2)
                    .allSatisfy(s -> assertThat(s.scenario() + " " + s.command()).isEqualTo("FailSafe STOP"));
            assertThat(after.get(after.size() - 1).scenario()).isEqualTo("ObstacleAvoidance");
        }
    }

    @Test
    void aFailureThatLastsIsRestartedLessAndLessOften() throws Exception {
        try (RobotTablesFixture f = mission()) {
            for (int i = 0; i < 6; i++) {
                step(f);
            }
            f.faulty.fail(ReachDestinationScenario.class);
            long first = f.engine.iteration() + 1;
            List<Long> restarts = new ArrayList<>();
            for (int i = 0; i < 120; i++) {
                String before = f.engine.memory().values().get(WatchFailures.RECORD_PREFIX + "ReachDestination");
                step(f);
                String now = f.engine.memory().values().get(WatchFailures.RECORD_PREFIX + "ReachDestination");
                if (now.startsWith("restarted") && !now.equals(before)) {
                    restarts.add(f.engine.iteration() - first);
                }
            }
            // gone at once; restarted 16 later, fails again 2 later (meta-rule, then its rule), waits 32, ...
            assertThat(restarts).containsExactly(16L, 16L + 2 + 32, 16L + 2 + 32 + 2 + 64);
        }
    }

    @Test
    void aSuggestionEnteredBeforeTheFailingPartIsWithdrawn() throws Exception {
        try (RobotTablesFixture f = mission()) {
            for (int i = 0; i < 6; i++) {
                step(f);
            }
            // A rule of obstacle avoidance that enters its suggestion, then throws; submitted, it runs
            // after this iteration's decision, so the fail-safe meets it as the previous iteration's failure.
            f.engine.submit(new EnterThenThrow());
            step(f); // EnterThenThrow runs at the end of this iteration
            step(f);
            RobotTablesFixture.Decision last = f.decisions.get(f.decisions.size() - 1);
            assertThat(last.suggestions()).doesNotContainValue("DRIVE 0.5 0.5");
            assertThat(f.engine.memory().values()).containsKey(WatchFailures.RECORD_PREFIX + "ObstacleAvoidance");
            assertThat(queuedScenarios(f)).as("avoidance's own rule still runs: no restart")
                    .contains("ObstacleAvoidance");
        }
    }

    @Test
    void anEpisodeInProgressSurvivesSaveAndResume() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            ProactiveEngine first = engine(db);
            first.startFresh(ScenarioRegistry.load().startUp(List.of(ORDER)));
            for (int i = 0; i < 4; i++) {
                first.runIteration();
            }
            first.submit(new EnterThenThrow());
            first.runIteration();
            first.runIteration();
            ProactiveEngine resumed = engine(db);
            resumed.start();
            assertThat(resumed.nextQueue()).extracting(Rule::name)
                    .containsExactlyElementsOf(first.nextQueue().stream().map(Rule::name).toList());
            assertThat(resumed.memory().values()).isEqualTo(first.memory().values()).isNotEmpty();
            resumed.runIteration();
        }
    }

    private static ProactiveEngine engine(TestDatabase db) {
        JdbcRobotTables tables = new JdbcRobotTables(db.dataSource(), 1);
        return ProactiveEngine.builder().robotId(1).store(new JdbcStateStore(db.dataSource()))
                .service(SensorReadings.class, tables).service(SensorRequests.class, tables)
                .service(MissionTables.class, tables).service(StrategyTable.class, tables)
                .service(EngineComments.class, tables).service(DriveProfile.class, DriveProfile.DEFAULT).build();
    }

    /** Enters a suggestion in avoidance's slot, then fails in its rules generation. */
    public static final class EnterThenThrow extends Rule {
        @Override
        public String scenario() {
            return ObstacleAvoidanceScenario.NAME;
        }

        @Override
        protected void actions(RuleContext ctx) {
            ctx.suggest("DRIVE 0.5 0.5");
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            throw new IllegalStateException("injected: fails after entering its suggestion");
        }
    }
}
