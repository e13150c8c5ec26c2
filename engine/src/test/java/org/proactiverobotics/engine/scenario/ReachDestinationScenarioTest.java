package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.scenario.destination.MoveToCheckpoint;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;

/** Scenario 2 alone: GetCheckpoint and MoveToCheckpoint steer to the checkpoints in order. */
class ReachDestinationScenarioTest {

    private static Suggestion suggestion(RobotTablesFixture f) {
        return f.engine.memory().commandArray().get(f.engine.memory().slotOf(ReachDestinationScenario.NAME));
    }

    @Test
    void itSteersTowardTheFirstCheckpointNotReached() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ReachDestination")) {
            f.checkpoint(0, 0, 2);
            f.checkpoint(1, 2, 2);
            f.gps(0, 0, 0);
            f.heading(0, 0.0); // facing +x; the checkpoint is to the left (+y)
            f.iterate(4);
            assertThat(f.engine.nextQueue()).anySatisfy(r -> assertThat(r).isInstanceOf(MoveToCheckpoint.class));
            Suggestion s = suggestion(f);
            assertThat(s.scenario()).isEqualTo("ReachDestination");
            String[] words = s.command().split(" ");
            assertThat(words[0]).isEqualTo("DRIVE");
            assertThat(Double.parseDouble(words[2])).as("right wheel faster: turning left").isGreaterThan(Double.parseDouble(words[1]));
        }
    }

    @Test
    void reachingACheckpointMarksItAndMovesOnToTheNextThenStopsAtTheEnd() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ReachDestination")) {
            f.checkpoint(0, 0, 2);
            f.checkpoint(1, 2, 2);
            f.gps(0, 0, 0);
            f.heading(0, Math.PI / 2);
            f.iterate(4);
            assertThat(suggestion(f).command()).isEqualTo("DRIVE 0.5000 0.5000"); // straight ahead, full speed

            f.gps(32, 0.0, 1.9); // within 0.8 × 0.25 m of checkpoint 0
            f.iterate(1);
            assertThat(f.reachedCheckpoints()).containsExactly("0");
            f.iterate(2); // GetCheckpoint runs, then MoveToCheckpoint for checkpoint 1
            assertThat(f.engine.nextQueue()).anySatisfy(r ->
                    assertThat(r).isInstanceOfSatisfying(MoveToCheckpoint.class, m -> assertThat(m.seq()).isEqualTo(1)));

            f.gps(64, 2.0, 2.05);
            f.iterate(3);
            assertThat(f.reachedCheckpoints()).containsExactly("0", "1");
            assertThat(suggestion(f).command()).isEqualTo("STOP");
        }
    }

    @Test
    void withoutCheckpointsItWaitsAndSuggestsNothing() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ReachDestination")) {
            f.gps(0, 0, 0);
            f.heading(0, 0);
            f.iterate(6);
            assertThat(suggestion(f)).isNull();
        }
    }
}
