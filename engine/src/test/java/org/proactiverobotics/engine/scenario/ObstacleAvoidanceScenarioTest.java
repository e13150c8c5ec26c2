package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;

/** Scenario 3 alone: AvoidObstacles engages near an obstacle, follows it, and lets go when past it. */
class ObstacleAvoidanceScenarioTest {

    private static final double FREE = 1.0;

    private static Suggestion suggestion(RobotTablesFixture f) {
        return f.engine.memory().commandArray().get(f.engine.memory().slotOf(ObstacleAvoidanceScenario.NAME));
    }

    private static double[] wheels(Suggestion s) {
        String[] w = s.command().split(" ");
        assertThat(w[0]).isEqualTo("DRIVE");
        return new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2])};
    }

    @Test
    void aClearWayGetsNoSuggestion() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ObstacleAvoidance")) {
            f.heading(0, 0);
            f.scan(0, FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            f.iterate(5);
            assertThat(suggestion(f)).isNull();
        }
    }

    @Test
    void aStaleScanStopsTheRobotRatherThanDriveBlind() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ObstacleAvoidance")) {
            f.scan(0, FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            f.heading(1000, 0); // the distance sensors have not been read for a second
            f.iterate(3);
            assertThat(suggestion(f).command()).isEqualTo("STOP");
        }
    }

    @Test
    void aReadingThatIsNotANumberCountsAsAnObstacleNotAsFreeSpace() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ObstacleAvoidance")) {
            f.heading(0, 0);
            f.scan(0, FREE, FREE, FREE, Double.NaN, FREE, FREE, FREE, FREE);
            f.iterate(3);
            assertThat(suggestion(f)).as("a NaN straight ahead engages avoidance").isNotNull();
        }
    }

    @Test
    void anImminentObstacleAheadStopsAndTurnsTowardTheFreerSide() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ObstacleAvoidance")) {
            f.heading(0, 0);
            // wall ahead, the right side cluttered, the left side free
            f.scan(0, 0.3, 0.3, 0.12, 0.10, 0.10, 0.2, FREE, FREE);
            f.iterate(3);
            double[] w = wheels(suggestion(f));
            assertThat(w[0]).as("left wheel backwards").isNegative();
            assertThat(w[1]).as("right wheel forwards: turning left on the spot").isPositive();
            assertThat(w[0] + w[1]).isCloseTo(0.0, org.assertj.core.data.Offset.offset(1e-9));
        }
    }

    @Test
    void itFollowsTheBoundaryAndLetsGoOnceTheTurnIsUndoneAndTheWayIsClear() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("ObstacleAvoidance")) {
            long t = 0;
            f.heading(t, 0);
            f.scan(t, FREE, FREE, 0.25, 0.2, 0.2, 0.25, FREE, FREE); // obstacle ahead: engage
            f.iterate(3);
            assertThat(suggestion(f)).isNotNull();
            // turned left by 90°, the obstacle now on the right: follow it
            t += 32;
            f.heading(t, Math.PI / 2);
            f.scan(t, 0.2, 0.28, FREE, FREE, FREE, FREE, FREE, FREE);
            f.iterate(1);
            double[] w = wheels(suggestion(f));
            assertThat(w[0]).as("driving on along the boundary").isPositive();
            assertThat(w[1]).isPositive();
            // still turned left: no release although the way ahead is clear
            f.scan(t += 32, FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            f.iterate(6);
            assertThat(suggestion(f)).isNotNull();
            // heading back where it met the obstacle and the way clear: it lets go
            f.heading(t += 32, 0.0);
            f.iterate(6);
            f.engine.memory().commandArray().clear(); // alone, no decision scenario clears it
            f.iterate(1);
            assertThat(suggestion(f)).isNull();
        }
    }
}
