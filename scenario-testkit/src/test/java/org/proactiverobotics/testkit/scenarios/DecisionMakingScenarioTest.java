package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.tables.StrategyTable;
import org.proactiverobotics.testkit.Decision;
import org.proactiverobotics.testkit.ScenarioKit;

/**
 * Scenario 5 alone: ReadRobotCommands obeys the PriorityArray and SendRobotCommand writes the
 * winner. The suggestions are entered by hand, as the scenarios would enter them.
 */
class DecisionMakingScenarioTest {

    private static final String DESTINATION = "ReachDestination";
    private static final String AVOIDANCE = "ObstacleAvoidance";

    /** Enters a suggestion in the scenario's slot, for the next step's decision. */
    private static void suggest(ScenarioKit kit, String scenario, String command) {
        SharedMemory memory = kit.memory();
        memory.commandArray().enter(memory.slotOf(scenario), command, scenario, kit.engine().engine().iteration());
    }

    /** Safety-first, with a time-out for one scenario's suggestions. */
    private static Strategy safetyFirstWithTimeout(String scenario, long timeoutMs) {
        return new Strategy(Strategy.SAFETY_FIRST, Strategy.named(Strategy.SAFETY_FIRST).priorities(), Map.of(scenario, timeoutMs));
    }

    @Test
    void theHighestPriorityThatHoldsACommandWinsAndIsSentTheNextIteration() {
        try (ScenarioKit kit = ScenarioKit.builder().start()) { // safety-first by default
            suggest(kit, DESTINATION, "DRIVE 0.5 0.5");
            suggest(kit, AVOIDANCE, "DRIVE 0 0.3");
            kit.step(); // ReadRobotCommands decides
            assertThat(kit.decision().winner()).isEqualTo(AVOIDANCE);
            assertThat(kit.sentCommands()).isEmpty();
            assertThat(kit.memory().commandArray().get(kit.memory().slotOf(AVOIDANCE))).as("suggestions live one iteration").isNull();
            kit.step(); // SendRobotCommand writes
            assertThat(kit.sentCommands()).containsExactly("DRIVE 0 0.3");
            assertThat(kit.sent()).singleElement().satisfies(s -> assertThat(s.scenario()).isEqualTo(AVOIDANCE));
        }
    }

    @Test
    void anEmptyHighestSlotFallsToTheNextAndNothingAtAllMeansStop() {
        try (ScenarioKit kit = ScenarioKit.builder().start()) {
            suggest(kit, DESTINATION, "DRIVE 0.5 0.5");
            kit.step(3);
            assertThat(kit.sentCommands()).containsExactly("DRIVE 0.5 0.5", "STOP");
            assertThat(kit.decision().winner()).isEqualTo("DecisionMaking");
        }
    }

    @Test
    void aStrategyChangedInTheTableDecidesTheNextIteration() {
        try (ScenarioKit kit = ScenarioKit.builder().start()) {
            suggest(kit, DESTINATION, "DRIVE 0.5 0.5");
            suggest(kit, AVOIDANCE, "DRIVE 0 0.3");
            kit.engine().writeStrategy(Strategy.named(Strategy.DESTINATION_FIRST));
            kit.step(2);
            assertThat(kit.sentCommands()).containsExactly("DRIVE 0.5 0.5");
        }
    }

    @Test
    void aSuggestionWithinItsTimeOutIsTakenAndOnePastItIsNotTheNextPriorityWins() {
        // avoidance's word holds 100 ms; steps at t = 0, 50, 100, 150, 200
        try (ScenarioKit kit = ScenarioKit.builder().strategy(safetyFirstWithTimeout(AVOIDANCE, 100)).timeStepMs(50).start()) {
            kit.robot().gps(0, 0); // the decision's clock
            suggest(kit, AVOIDANCE, "DRIVE 0 0.3"); // entered once, then silent
            for (int i = 0; i < 5; i++) {
                suggest(kit, DESTINATION, "DRIVE 0.5 0.5"); // entered every iteration
                kit.step();
            }
            assertThat(kit.decisions()).extracting(Decision::winner).containsExactly(
                    AVOIDANCE, AVOIDANCE, AVOIDANCE, DESTINATION, DESTINATION);
            assertThat(kit.decisions().get(3).suggestions()).as("expired: cleared before anyone sees it")
                    .doesNotContainKey(AVOIDANCE);
            assertThat(kit.memory().commandArray().get(kit.memory().slotOf(AVOIDANCE))).isNull();
            assertThat(kit.memory().commandArray().get(kit.memory().slotOf(DESTINATION))).as("time-out 0: one iteration").isNull();
        }
    }

    @Test
    void aNewSuggestionStartsItsTimeOutAgain() {
        try (ScenarioKit kit = ScenarioKit.builder().strategy(safetyFirstWithTimeout(AVOIDANCE, 100)).timeStepMs(64).start()) {
            kit.robot().gps(0, 0);
            for (int i = 0; i < 5; i++) {
                long t = kit.simTimeMs(); // 0, 64, 128, 192, 256
                if (t == 0 || t == 128) {
                    suggest(kit, AVOIDANCE, "DRIVE 0 0." + t);
                }
                suggest(kit, DESTINATION, "DRIVE 0.5 0.5");
                kit.step();
            }
            assertThat(kit.decisions()).extracting(Decision::command).containsExactly(
                    "DRIVE 0 0.0", "DRIVE 0 0.0", "DRIVE 0 0.128", "DRIVE 0 0.128", "DRIVE 0.5 0.5");
        }
    }

    @Test
    void theTimeOutsAreReadFromTheStrategyTable() {
        try (ScenarioKit kit = ScenarioKit.builder().strategy(safetyFirstWithTimeout("BatteryMonitor", 250)).start()) {
            List<StrategyTable.Entry> rows = kit.engine().tables().strategy().read();
            assertThat(rows).extracting(StrategyTable.Entry::scenario).containsExactly(DESTINATION, "BatteryMonitor", AVOIDANCE);
            assertThat(rows).extracting(StrategyTable.Entry::timeoutMs).containsExactly(0L, 250L, 0L);
            assertThat(Strategy.named(Strategy.SAFETY_FIRST).rows(kit.engine().slots())).allSatisfy(e -> assertThat(e.timeoutMs()).isZero());
            assertThatThrownBy(() -> rows.get(0).withTimeoutMs(-1)).isInstanceOf(IllegalArgumentException.class);
        }
    }

    @Test
    void strategiesAreNamedAndAnUnknownNameListsTheKnownOnes() {
        assertThat(Strategy.names()).startsWith(Strategy.SAFETY_FIRST);
        assertThat(Strategy.named(Strategy.SAFETY_FIRST).rows(Map.of(DESTINATION, 0, "BatteryMonitor", 1, AVOIDANCE, 2)))
                .extracting(e -> e.scenario() + "=" + e.priority())
                .containsExactly("ReachDestination=1", "BatteryMonitor=2", "ObstacleAvoidance=3");
        assertThatThrownBy(() -> Strategy.named("yolo")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("yolo").hasMessageContaining(String.join(", ", Strategy.names()));
        assertThat(List.copyOf(Strategy.names())).doesNotHaveDuplicates();
    }
}
