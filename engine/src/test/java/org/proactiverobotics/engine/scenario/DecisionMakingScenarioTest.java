package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.tables.StrategyTable;

/** Scenario 5 alone: ReadRobotCommands obeys the PriorityArray and SendRobotCommand writes the winner. */
class DecisionMakingScenarioTest {

    private static void suggest(RobotTablesFixture f, int slot, String command, String scenario) {
        CommandArray commands = f.engine.memory().commandArray();
        commands.enter(slot, command, scenario, f.engine.iteration());
    }

    @Test
    void theHighestPriorityThatHoldsACommandWinsAndIsSentTheNextIteration() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DecisionMaking")) {
            f.tables.write(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots()));
            f.iterate(2);
            suggest(f, 0, "DRIVE 0.5 0.5", "ReachDestination");
            suggest(f, 2, "DRIVE 0 0.3", "ObstacleAvoidance");
            f.iterate(1); // ReadRobotCommands decides
            assertThat(f.commands()).isEmpty();
            assertThat(f.engine.memory().commandArray().get(2)).as("suggestions live one iteration").isNull();
            f.iterate(1); // SendRobotCommand writes
            assertThat(f.commands()).containsExactly("DRIVE 0 0.3");
        }
    }

    @Test
    void anEmptyHighestSlotFallsToTheNextAndNothingAtAllMeansStop() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DecisionMaking")) {
            f.tables.write(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots()));
            f.iterate(2);
            suggest(f, 0, "DRIVE 0.5 0.5", "ReachDestination");
            f.iterate(2);
            f.iterate(1);
            assertThat(f.commands()).containsExactly("DRIVE 0.5 0.5", "STOP");
        }
    }

    @Test
    void aStrategyChangedInTheTableDecidesTheNextIteration() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DecisionMaking")) {
            f.tables.write(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots()));
            f.iterate(2);
            suggest(f, 0, "DRIVE 0.5 0.5", "ReachDestination");
            suggest(f, 2, "DRIVE 0 0.3", "ObstacleAvoidance");
            f.tables.write(Strategy.named(Strategy.DESTINATION_FIRST).rows(f.engine.memory().slots()));
            f.iterate(2);
            assertThat(f.commands()).containsExactly("DRIVE 0.5 0.5");
        }
    }

    @Test
    void aSuggestionWithinItsTimeOutIsTakenAndOnePastItIsNotTheNextPriorityWins() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DecisionMaking")) {
            List<StrategyTable.Entry> strategy = new ArrayList<>(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots()));
            strategy.set(2, strategy.get(2).withTimeoutMs(100)); // avoidance's word holds 100 ms
            f.tables.write(strategy);
            f.iterate(2);
            suggest(f, 2, "DRIVE 0 0.3", "ObstacleAvoidance"); // entered once, then silent
            for (long t : new long[] {0, 64, 100, 132, 164}) {
                f.gps(t, 0, 0);
                suggest(f, 0, "DRIVE 0.5 0.5", "ReachDestination"); // entered every iteration
                f.iterate(1);
            }
            assertThat(f.decisions).extracting(RobotTablesFixture.Decision::winner).containsExactly(
                    "ObstacleAvoidance", "ObstacleAvoidance", "ObstacleAvoidance", "ReachDestination", "ReachDestination");
            assertThat(f.decisions.get(3).suggestions()).as("expired: cleared before anyone sees it")
                    .doesNotContainKey("ObstacleAvoidance");
            assertThat(f.engine.memory().commandArray().get(2)).isNull();
            assertThat(f.engine.memory().commandArray().get(0)).as("time-out 0: one iteration").isNull();
        }
    }

    @Test
    void aNewSuggestionStartsItsTimeOutAgain() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DecisionMaking")) {
            List<StrategyTable.Entry> strategy = new ArrayList<>(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots()));
            strategy.set(2, strategy.get(2).withTimeoutMs(100));
            f.tables.write(strategy);
            f.iterate(2);
            for (long t : new long[] {0, 64, 128, 192, 256}) {
                f.gps(t, 0, 0);
                if (t == 0 || t == 128) {
                    suggest(f, 2, "DRIVE 0 0." + t, "ObstacleAvoidance");
                }
                suggest(f, 0, "DRIVE 0.5 0.5", "ReachDestination");
                f.iterate(1);
            }
            assertThat(f.decisions).extracting(RobotTablesFixture.Decision::command).containsExactly(
                    "DRIVE 0 0.0", "DRIVE 0 0.0", "DRIVE 0 0.128", "DRIVE 0 0.128", "DRIVE 0.5 0.5");
        }
    }

    @Test
    void theTimeOutsAreReadFromTheStrategyTable() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DecisionMaking")) {
            List<StrategyTable.Entry> strategy = new ArrayList<>(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots()));
            strategy.set(1, strategy.get(1).withTimeoutMs(250));
            f.tables.write(strategy);
            assertThat(f.tables.read()).extracting(StrategyTable.Entry::timeoutMs).containsExactly(0L, 250L, 0L);
            assertThat(Strategy.named(Strategy.SAFETY_FIRST).rows(f.engine.memory().slots())).allSatisfy(e -> assertThat(e.timeoutMs()).isZero());
            assertThatThrownBy(() -> strategy.get(0).withTimeoutMs(-1)).isInstanceOf(IllegalArgumentException.class);
        }
    }

    @Test
    void strategiesAreNamedAndAnUnknownNameListsTheKnownOnes() {
        assertThat(Strategy.names()).startsWith(Strategy.SAFETY_FIRST);
        assertThat(Strategy.named(Strategy.SAFETY_FIRST).rows(java.util.Map.of("ReachDestination", 0, "BatteryMonitor", 1,
                "ObstacleAvoidance", 2))).extracting(e -> e.scenario() + "=" + e.priority())
                .containsExactly("ReachDestination=1", "BatteryMonitor=2", "ObstacleAvoidance=3");
        assertThatThrownBy(() -> Strategy.named("yolo")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("yolo").hasMessageContaining(String.join(", ", Strategy.names()));
        assertThat(List.copyOf(Strategy.names())).doesNotHaveDuplicates();
    }
}
