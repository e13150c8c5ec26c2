package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import org.assertj.core.data.Offset;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.testkit.ScenarioKit;

/** Scenario 3 alone: AvoidObstacles engages near an obstacle, follows it, and lets go when past it. */
class ObstacleAvoidanceScenarioTest {

    private static final double FREE = 1.0;
    private static final String AVOIDANCE = ObstacleAvoidanceScenario.NAME;

    private static ScenarioKit kit() {
        return ScenarioKit.builder().builtIn(AVOIDANCE).start();
    }

    private static double[] wheels(String command) {
        String[] w = command.split(" ");
        assertThat(w[0]).isEqualTo("DRIVE");
        return new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2])};
    }

    @Test
    void aClearWayGetsNoSuggestion() {
        try (ScenarioKit kit = kit()) {
            kit.robot().headingDeg(0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step(3);
            assertThat(kit.suggestions(AVOIDANCE)).hasSize(3).containsOnlyNulls();
        }
    }

    @Test
    void aStaleScanStopsTheRobotRatherThanDriveBlind() {
        try (ScenarioKit kit = ScenarioKit.builder().builtIn(AVOIDANCE).timeStepMs(1000).start()) {
            kit.robot().headingDeg(0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).isNull();
            kit.robot().silent(Sensor.DS);
            kit.step(); // the distance sensors have not been read for a second
            assertThat(kit.suggestion(AVOIDANCE)).isEqualTo("STOP");
        }
    }

    @Test
    void aReadingThatIsNotANumberCountsAsAnObstacleNotAsFreeSpace() {
        try (ScenarioKit kit = kit()) {
            kit.robot().headingDeg(0).scan(FREE, FREE, FREE, Double.NaN, FREE, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).as("a NaN straight ahead engages avoidance").isNotNull();
        }
    }

    @Test
    void anImminentObstacleAheadStopsAndTurnsTowardTheFreerSide() {
        try (ScenarioKit kit = kit()) {
            // wall ahead, the right side cluttered, the left side free
            kit.robot().headingDeg(0).scan(0.3, 0.3, 0.12, 0.10, 0.10, 0.2, FREE, FREE);
            kit.step();
            double[] w = wheels(kit.suggestion(AVOIDANCE));
            assertThat(w[0]).as("left wheel backwards").isNegative();
            assertThat(w[1]).as("right wheel forwards: turning left on the spot").isPositive();
            assertThat(w[0] + w[1]).isCloseTo(0.0, Offset.offset(1e-9));
        }
    }

    @Test
    void itFollowsTheBoundaryAndLetsGoOnceTheTurnIsUndoneAndTheWayIsClear() {
        try (ScenarioKit kit = kit()) {
            kit.robot().headingDeg(0).scan(FREE, FREE, 0.25, 0.2, 0.2, 0.25, FREE, FREE); // obstacle ahead: engage
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).isNotNull();
            // turned left by 90°, the obstacle now on the right: follow it
            kit.robot().headingDeg(90).scan(0.2, 0.28, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step();
            double[] w = wheels(kit.suggestion(AVOIDANCE));
            assertThat(w[0]).as("driving on along the boundary").isPositive();
            assertThat(w[1]).isPositive();
            // still turned left: no release although the way ahead is clear
            kit.robot().scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step(6);
            assertThat(kit.suggestions(AVOIDANCE)).as("engaged all along").doesNotContainNull();
            // heading back where it met the obstacle and the way clear: it lets go
            kit.robot().headingDeg(0);
            kit.step(7);
            assertThat(kit.suggestion(AVOIDANCE)).isNull();
        }
    }
}
