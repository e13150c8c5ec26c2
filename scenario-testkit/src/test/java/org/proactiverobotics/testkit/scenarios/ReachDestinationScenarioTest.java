package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.scenario.destination.MoveToCheckpoint;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.testkit.ScenarioKit;

/** Scenario 2 alone: GetCheckpoint and MoveToCheckpoint steer to the checkpoints in order. */
class ReachDestinationScenarioTest {

    private static final String DESTINATION = ReachDestinationScenario.NAME;

    private static ScenarioKit kit() {
        return ScenarioKit.builder().builtIn(DESTINATION).start();
    }

    @Test
    void itSteersTowardTheFirstCheckpointNotReached() {
        try (ScenarioKit kit = kit()) {
            kit.mission().checkpoint(0, 2).checkpoint(2, 2);
            kit.robot().gps(0, 0).headingDeg(0); // facing +x; the checkpoint is to the left (+y)
            kit.step(2);
            assertThat(kit.engine().engine().nextQueue()).anySatisfy(r -> assertThat(r).isInstanceOf(MoveToCheckpoint.class));
            assertThat(kit.decision().suggestions()).containsKey(DESTINATION);
            String[] words = kit.suggestion(DESTINATION).split(" ");
            assertThat(words[0]).isEqualTo("DRIVE");
            assertThat(Double.parseDouble(words[2])).as("right wheel faster: turning left").isGreaterThan(Double.parseDouble(words[1]));
        }
    }

    @Test
    void reachingACheckpointMarksItAndMovesOnToTheNextThenStopsAtTheEnd() {
        try (ScenarioKit kit = kit()) {
            kit.mission().checkpoint(0, 2).checkpoint(2, 2);
            kit.robot().gps(0, 0).headingDeg(90);
            kit.step(2);
            assertThat(kit.suggestion(DESTINATION)).isEqualTo("DRIVE 0.5000 0.5000"); // straight ahead, full speed

            kit.robot().gps(0.0, 1.9); // within 0.8 × 0.25 m of checkpoint 0
            kit.step();
            assertThat(kit.reachedCheckpoints()).containsExactly(0);
            kit.step(2); // GetCheckpoint runs, then MoveToCheckpoint for checkpoint 1
            assertThat(kit.engine().engine().nextQueue()).anySatisfy(r ->
                    assertThat(r).isInstanceOfSatisfying(MoveToCheckpoint.class, m -> assertThat(m.seq()).isEqualTo(1)));

            kit.robot().gps(2.0, 2.05);
            kit.step(3);
            assertThat(kit.reachedCheckpoints()).containsExactly(0, 1);
            assertThat(kit.suggestion(DESTINATION)).isEqualTo("STOP");
        }
    }

    @Test
    void withoutCheckpointsItWaitsAndSuggestsNothing() {
        try (ScenarioKit kit = kit()) {
            kit.robot().gps(0, 0).headingDeg(0);
            kit.step(4);
            assertThat(kit.suggestions(DESTINATION)).hasSize(4).containsOnlyNulls();
        }
    }
}
