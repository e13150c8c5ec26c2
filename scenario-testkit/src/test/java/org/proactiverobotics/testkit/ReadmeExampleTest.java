package org.proactiverobotics.testkit;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.Sensor;

/** The example of the kit's README, line for line: it stays true. */
class ReadmeExampleTest {

    @Test
    void itCreepsNearAnObstacleAndStopsWhenTheScanGoesQuiet() {
        try (ScenarioKit kit = ScenarioKit.builder()
                .scenario(new SpeedGovernorScenario())   // yours: a Scenario and its Rules
                .builtIn("ObstacleAvoidance")            // built-in ones too, if you like
                .start()) {                              // fresh engine, fresh embedded H2
            kit.robot().gps(0.0, -4.0).headingDeg(90).scan(1, 1, 1, 0.3, 0.3, 1, 1, 1).battery(80);
            kit.step();                                  // 32 simulated ms, one engine iteration
            assertThat(kit.suggestion("SpeedGovernor")).isEqualTo("FORWARD 0.1");
            assertThat(kit.decision().winner()).isEqualTo("SpeedGovernor");

            kit.robot().silent(Sensor.DS);               // the scan stops coming: it goes stale
            kit.step(4);
            assertThat(kit.suggestions("SpeedGovernor"))
                    .containsExactly("FORWARD 0.1", "FORWARD 0.1", "FORWARD 0.1", "FORWARD 0.1", "STOP");
            assertThat(kit.sentCommands()).startsWith("FORWARD 0.1");
            assertThat(kit.failures()).isEmpty();
        }
    }
}
