package com.example.governor;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.testkit.ScenarioKit;

/** SpeedGovernor alone on the real engine, the robot's readings scripted step by step. */
class SpeedGovernorTest {

    private static final double FREE = 1.0;

    private static ScenarioKit kit() {
        ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).start();
        kit.mission().checkpoint(0.0, 3.0);
        kit.robot().gps(0.0, -1.0).headingDeg(90);
        return kit;
    }

    /** Both wheel speeds of a DRIVE command, m/s. */
    private static double[] wheels(String command) {
        String[] w = command.split(" ");
        assertThat(w[0]).isEqualTo("DRIVE");
        return new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2])};
    }

    @Test
    void aClearWayIsLeftToTheOthers() {
        try (ScenarioKit kit = kit()) {
            kit.robot().scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step(3);
            assertThat(kit.suggestions("SpeedGovernor")).containsOnlyNulls();
            assertThat(kit.failures()).isEmpty();
        }
    }

    @Test
    void anObstacleAheadSlowsTheRobotTowardItsCheckpoint() {
        try (ScenarioKit kit = kit()) {
            kit.robot().scan(FREE, FREE, FREE, 0.4, 0.45, FREE, FREE, FREE);
            kit.step();
            double[] w = wheels(kit.suggestion("SpeedGovernor"));
            assertThat(w[0]).isPositive().isLessThanOrEqualTo(0.2);
            assertThat(w[1]).isPositive().isLessThanOrEqualTo(0.2);
            assertThat(kit.decision().winner()).isEqualTo("SpeedGovernor");
        }
    }

    @Test
    void anUnreadableDistanceCountsAsNearAndNoPositionMeansNoSuggestion() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).start()) {
            kit.mission().checkpoint(0.0, 3.0);
            kit.robot().scan(FREE, FREE, FREE, Double.NaN, FREE, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion("SpeedGovernor")).as("no GPS yet: nothing to steer by").isNull();
            kit.robot().gps(0.0, -1.0).headingDeg(90);
            kit.step();
            assertThat(kit.suggestion("SpeedGovernor")).as("NaN ahead reads as near").startsWith("DRIVE");
            assertThat(kit.failures()).isEmpty();
        }
    }

    @Test
    void itWinsOverReachDestinationExactlyWhenTheStrategyRanksItHigher() {
        String governorFirst = "{\"priorities\": {\"SpeedGovernor\": 2, \"ReachDestination\": 1}}";
        String governorLast = "{\"priorities\": {\"SpeedGovernor\": 1, \"ReachDestination\": 2}}";
        for (String strategy : new String[] {governorFirst, governorLast}) {
            try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).builtIn("ReachDestination")
                    .strategyJson(strategy).start()) {
                kit.mission().checkpoint(0.0, 3.0);
                kit.robot().gps(0.0, -1.0).headingDeg(90).scan(FREE, FREE, FREE, 0.4, 0.4, FREE, FREE, FREE);
                kit.step(2);
                String expected = strategy.equals(governorFirst) ? "SpeedGovernor" : "ReachDestination";
                assertThat(kit.decision().winner()).isEqualTo(expected);
            }
        }
    }
}
