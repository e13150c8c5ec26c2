package com.example.park;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.testkit.ScenarioKit;

/** ReturnToStation with ReachDestination, which marks the checkpoint reached: then it heads home and parks. */
class ReturnToStationTest {

    @Test
    void onceEveryCheckpointIsReachedItHeadsForTheStationAndStopsThere() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new ReturnToStationScenario()).builtIn("ReachDestination")
                .strategyJson("{\"priorities\": {\"ReturnToStation\": 2, \"ReachDestination\": 1}}").start()) {
            kit.mission().checkpoint(1.0, 0.0).station(-2.0, 0.0, 100);
            kit.robot().gps(0.0, 0.0).headingDeg(180);
            kit.step(2);
            assertThat(kit.suggestion("ReturnToStation")).as("checkpoint not reached yet").isNull();

            kit.robot().gps(1.0, 0.0); // on the checkpoint: ReachDestination marks it
            kit.step(3);
            assertThat(kit.reachedCheckpoints()).containsExactly(0);
            assertThat(kit.suggestion("ReturnToStation")).startsWith("DRIVE");
            assertThat(kit.decision().winner()).isEqualTo("ReturnToStation");

            kit.robot().gps(-1.95, 0.05); // at the station
            kit.step();
            assertThat(kit.suggestion("ReturnToStation")).isEqualTo("STOP");
        }
    }

    @Test
    void withoutAStationItSuggestsNothingAndDoesNotFail() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new ReturnToStationScenario()).builtIn("ReachDestination").start()) {
            kit.mission().checkpoint(0.0, 0.0);
            kit.robot().gps(0.0, 0.0).headingDeg(0);
            kit.step(4);
            assertThat(kit.reachedCheckpoints()).containsExactly(0);
            assertThat(kit.suggestion("ReturnToStation")).isNull();
            assertThat(kit.failures()).isEmpty();
            assertThat(kit.scheduled()).contains("ReturnToStation/Park");
        }
    }
}
