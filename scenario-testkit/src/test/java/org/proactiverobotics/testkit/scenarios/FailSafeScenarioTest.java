package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.RuleFailure;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.scenario.battery.BatteryMonitorScenario;
import org.proactiverobotics.engine.scenario.dataacquisition.DataAcquisitionScenario;
import org.proactiverobotics.engine.scenario.decision.DecisionMakingScenario;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.scenario.failsafe.FailSafeScenario;
import org.proactiverobotics.engine.scenario.failsafe.WatchFailures;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.testkit.Decision;
import org.proactiverobotics.testkit.ScenarioKit;
import org.proactiverobotics.testkit.SentCommand;

/**
 * The fail-safe scenario with the five robot scenarios: a rule that throws, in each scenario in
 * turn, while the robot sits before an obstacle on its way to a checkpoint.
 */
class FailSafeScenarioTest {

    static final String[] ORDER = {"DataAcquisition", "BatteryMonitor", "ReachDestination", "ObstacleAvoidance",
            FailSafeScenario.NAME, "DecisionMaking"};
    private static final double FREE = 1.0;

    private final FaultyTables faulty = new FaultyTables();

    static Stream<Arguments> scenarios() {
        return Stream.of(
                Arguments.of(DataAcquisitionScenario.NAME, DataAcquisitionScenario.class),
                Arguments.of(BatteryMonitorScenario.NAME, BatteryMonitorScenario.class),
                Arguments.of(ReachDestinationScenario.NAME, ReachDestinationScenario.class),
                Arguments.of(ObstacleAvoidanceScenario.NAME, ObstacleAvoidanceScenario.class),
                Arguments.of(DecisionMakingScenario.NAME, DecisionMakingScenario.class));
    }

    /** Every scenario, safety-first, a robot at the origin facing the checkpoint, an obstacle 0.1 m ahead (within braking reach). */
    private ScenarioKit mission() {
        ScenarioKit kit = ScenarioKit.builder().builtIn(ORDER).faults(faulty::wrap).start();
        kit.mission().checkpoint(0.0, 3.0).station(-3.0, 0.0, 100.0);
        kit.robot().gps(0.0, 0.0).headingDeg(90).scan(FREE, FREE, 0.15, 0.1, 0.1, 0.15, FREE, FREE).battery(90.0);
        return kit;
    }

    /** One control step; the kit's start-up ran iterations 1 and 2. */
    private static List<RuleFailure> step(ScenarioKit kit) {
        kit.step();
        return kit.failures();
    }

    private static Set<String> queuedScenarios(ScenarioKit kit) {
        return kit.engine().engine().nextQueue().stream().map(Rule::scenario).collect(Collectors.toSet());
    }

    private static List<SentCommand> sentSince(ScenarioKit kit, int before) {
        List<SentCommand> sent = kit.sent();
        return sent.subList(before, sent.size());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenarios")
    void aRuleThatThrowsIsContainedTheOthersGoOnAndTheScenarioComesBack(String failing, Class<?> scenarioClass) {
        try (ScenarioKit kit = mission()) {
            for (int i = 0; i < 4; i++) {
                assertThat(step(kit)).isEmpty();
            }
            assertThat(kit.decisions()).last().extracting(Decision::winner).isEqualTo("ObstacleAvoidance");
            long failAt = kit.engine().engine().iteration() + 1;
            int sentBefore = kit.sent().size();
            int decisionsBefore = kit.decisions().size();

            faulty.fail(scenarioClass);
            List<RuleFailure> failures = new ArrayList<>();
            for (int i = 0; i < 8; i++) {
                failures.addAll(step(kit));
            }
            // The iteration goes on: only the failing scenario failed, every other one still runs.
            assertThat(failures).isNotEmpty().allSatisfy(x -> assertThat(x.scenario()).isEqualTo(failing));
            assertThat(queuedScenarios(kit)).containsAll(Stream.of(ORDER).filter(s -> !s.equals(failing)).toList());
            // No decision after the failure saw a suggestion of the failing scenario ...
            assertThat(kit.decisions().subList(decisionsBefore, kit.decisions().size()))
                    .allSatisfy(d -> assertThat(d.suggestions()).doesNotContainKey(failing));
            // ... and no command of it was sent, not even the one decided just before it failed.
            List<SentCommand> after = sentSince(kit, sentBefore);
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
            assertThat(kit.memory().values().get(WatchFailures.RECORD_PREFIX + failing))
                    .startsWith("gone at iteration " + goneAt);

            faulty.heal();
            for (int i = 0; i < (int) WatchFailures.RESTART_AFTER_ITERATIONS + 4; i++) {
                assertThat(step(kit)).isEmpty();
            }
            assertThat(kit.memory().values().get(WatchFailures.RECORD_PREFIX + failing)).startsWith("back after 1 restart(s)");
            assertThat(queuedScenarios(kit)).contains(failing);
            assertThat(kit.scheduled()).as("the decision still runs last").last().isEqualTo("DecisionMaking/ReadRobotCommands");
            // back to normal: the collision monitor vetoes driving into the obstacle at least every other step
            // (a restarted scenario runs after it, so it vets that scenario's last decided command), or the way
            // found goes round it on the spot
            List<Decision> lastTwo = kit.decisions().subList(kit.decisions().size() - 2, kit.decisions().size());
            assertThat(lastTwo).as(lastTwo.toString()).anySatisfy(d -> assertThat(d.winner().equals("ObstacleAvoidance")
                    || turnsOnTheSpot(d.command())).isTrue());
        }
    }

    /** Whether a command turns the robot on the spot (its wheels at opposite speeds), which a disc robot can always do. */
    private static boolean turnsOnTheSpot(String command) {
        String[] w = command.split(" ");
        return w[0].equals("DRIVE") && Math.abs(Double.parseDouble(w[1]) + Double.parseDouble(w[2])) < 1e-6;
    }

    @Test
    void aDataAcquisitionRuleLostToOneFaultIsRestoredSoItsSensorKeepsBeingRead() {
        try (ScenarioKit kit = mission()) {
            kit.step(2);
            faulty.failOnce(Sensor.DS);
            List<RuleFailure> failures = step(kit);
            assertThat(failures).singleElement().satisfies(x -> assertThat(x.rule()).isEqualTo("GetDS"));
            step(kit);
            assertThat(kit.scheduled()).contains("DataAcquisition/GetDS");
            step(kit); // the robot answers what is pending ...
            assertThat(kit.requestedSensors()).as("... and the scan is asked for again").contains("DS");
            assertThat(kit.memory().values().get(WatchFailures.RECORD_PREFIX + "DataAcquisition"))
                    .startsWith("running again with 1 lost rule(s) restored");
        }
    }

    @Test
    void deadObstacleAvoidanceUnderSafetyFirstStopsTheRobotUntilItIsBack() {
        try (ScenarioKit kit = mission()) {
            kit.step(4);
            int sentBefore = kit.sent().size();
            faulty.fail(ObstacleAvoidanceScenario.class);
            step(kit);
            faulty.heal();
            kit.step((int) WatchFailures.RESTART_AFTER_ITERATIONS);
            step(kit); // the meta-rule runs: STOP still stands in
            step(kit); // AvoidObstacles runs again and wins the decision ...
            step(kit); // ... whose command is sent now
            List<SentCommand> after = sentSince(kit, sentBefore);
            // The command decided before the failure is withdrawn for a STOP, then the fail-safe's STOP
            // until avoidance is back.
            assertThat(after.get(0)).extracting(SentCommand::scenario, SentCommand::command)
                    .containsExactly("DecisionMaking", "STOP");
            assertThat(after.subList(1, after.size() - 1)).hasSize((int) WatchFailures.RESTART_AFTER_ITERATIONS + 2)
                    .allSatisfy(s -> assertThat(s.scenario() + " " + s.command()).isEqualTo("FailSafe STOP"));
            assertThat(after.get(after.size() - 1).scenario()).isEqualTo("ObstacleAvoidance");
        }
    }

    @Test
    void aFailureThatLastsIsRestartedLessAndLessOften() {
        try (ScenarioKit kit = mission()) {
            kit.step(4);
            faulty.fail(ReachDestinationScenario.class);
            long first = kit.engine().engine().iteration() + 1;
            List<Long> restarts = new ArrayList<>();
            for (int i = 0; i < 120; i++) {
                String before = kit.memory().values().get(WatchFailures.RECORD_PREFIX + "ReachDestination");
                step(kit);
                String now = kit.memory().values().get(WatchFailures.RECORD_PREFIX + "ReachDestination");
                if (now.startsWith("restarted") && !now.equals(before)) {
                    restarts.add(kit.engine().engine().iteration() - first);
                }
            }
            // gone at once; restarted 16 later, fails again 2 later (meta-rule, then its rule), waits 32, ...
            assertThat(restarts).containsExactly(16L, 16L + 2 + 32, 16L + 2 + 32 + 2 + 64);
        }
    }

    @Test
    void aSuggestionEnteredBeforeTheFailingPartIsWithdrawn() {
        try (ScenarioKit kit = mission()) {
            kit.step(4);
            // A rule of obstacle avoidance that enters its suggestion, then throws; submitted, it runs
            // after this iteration's decision, so the fail-safe meets it as the previous iteration's failure.
            kit.engine().engine().submit(new EnterThenThrow());
            step(kit); // EnterThenThrow runs at the end of this iteration
            step(kit);
            assertThat(kit.decision().suggestions()).doesNotContainValue("DRIVE 0.5 0.5");
            assertThat(kit.memory().values()).containsKey(WatchFailures.RECORD_PREFIX + "ObstacleAvoidance");
            assertThat(queuedScenarios(kit)).as("avoidance's own rule still runs: no restart")
                    .contains("ObstacleAvoidance");
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void anEpisodeInProgressSurvivesSaveAndResume(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             ScenarioKit kit = ScenarioKit.builder().builtIn(ORDER).database(db.dataSource()).start()) {
            kit.step(2);
            kit.engine().engine().submit(new EnterThenThrow());
            kit.step(2);
            RobotEngine resumed = RobotEngine.builder().database(kit.database()).build();
            assertThat(resumed.resume()).isTrue();
            assertThat(resumed.engine().nextQueue()).extracting(Rule::toString).containsExactlyElementsOf(kit.scheduled());
            assertThat(resumed.engine().memory().values()).isEqualTo(kit.memory().values()).isNotEmpty();
            resumed.iterate();
        }
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
