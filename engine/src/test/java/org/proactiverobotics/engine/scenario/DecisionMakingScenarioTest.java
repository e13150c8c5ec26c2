package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.scenario.decision.Strategies;

/** Scenario 5 alone: ReadRobotCommands obeys the PriorityArray and SendRobotCommand writes the winner. */
class DecisionMakingScenarioTest {

    private static void suggest(RobotTablesFixture f, int slot, String command, String scenario) {
        CommandArray commands = f.engine.memory().commandArray();
        commands.enter(slot, command, scenario, f.engine.iteration());
    }

    @Test
    void theHighestPriorityThatHoldsACommandWinsAndIsSentTheNextIteration() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DecisionMaking")) {
            f.tables.write(Strategies.named(Strategies.SAFETY_FIRST));
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
            f.tables.write(Strategies.named(Strategies.SAFETY_FIRST));
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
            f.tables.write(Strategies.named(Strategies.SAFETY_FIRST));
            f.iterate(2);
            suggest(f, 0, "DRIVE 0.5 0.5", "ReachDestination");
            suggest(f, 2, "DRIVE 0 0.3", "ObstacleAvoidance");
            f.tables.write(Strategies.named(Strategies.DESTINATION_FIRST));
            f.iterate(2);
            assertThat(f.commands()).containsExactly("DRIVE 0.5 0.5");
        }
    }

    @Test
    void strategiesAreNamedAndAnUnknownNameListsTheKnownOnes() {
        assertThat(Strategies.names()).startsWith(Strategies.SAFETY_FIRST);
        assertThat(Strategies.named(Strategies.SAFETY_FIRST)).extracting(e -> e.scenario() + "=" + e.priority())
                .containsExactly("ReachDestination=1", "BatteryMonitor=2", "ObstacleAvoidance=3");
        assertThatThrownBy(() -> Strategies.named("yolo")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("yolo").hasMessageContaining(String.join(", ", Strategies.names()));
        assertThat(List.copyOf(Strategies.names())).doesNotHaveDuplicates();
    }
}
