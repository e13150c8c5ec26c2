package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.assertj.core.data.Offset;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.scenario.mapping.MappingScenario;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.testkit.ScenarioKit;

/**
 * Scenario 3 alone, as a collision monitor: AvoidObstacles vets the command another scenario
 * (here a test driver ranked below it) would have the robot drive, and speaks only when that
 * command would hit something within the braking reach.
 */
class ObstacleAvoidanceScenarioTest {

    private static final double FREE = 1.0;
    private static final String AVOIDANCE = ObstacleAvoidanceScenario.NAME;
    /** What the driver suggests every iteration (one test at a time: the tests of this class run in order). */
    private static volatile String driverCommand = "DRIVE 0.5000 0.5000";

    /** A scenario that suggests {@link #driverCommand} every iteration. */
    public static final class Driver implements Scenario {
        @Override
        public String name() {
            return "Driver";
        }

        @Override
        public List<Rule> firstRules() {
            return List.of(new Drive());
        }
    }

    /** The driver's rule. */
    public static final class Drive extends Rule {
        @Override
        public String scenario() {
            return "Driver";
        }

        @Override
        protected void actions(RuleContext ctx) {
            ctx.suggest(driverCommand);
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }

    private static ScenarioKit kit(String command) {
        driverCommand = command;
        return ScenarioKit.builder().scenario(new Driver()).builtIn(AVOIDANCE)
                .strategyJson("{\"priorities\": {\"ObstacleAvoidance\": 2, \"Driver\": 1}}").start();
    }

    /** A kit that also maps, the robot first turned once round on the spot with every ray free (the map sees round it). */
    private static ScenarioKit mappedKit(String command) {
        driverCommand = command;
        ScenarioKit kit = ScenarioKit.builder().scenario(new Driver()).builtIn(AVOIDANCE, MappingScenario.NAME)
                .strategyJson("{\"priorities\": {\"ObstacleAvoidance\": 2, \"Driver\": 1}}").start();
        for (int deg = 0; deg < 360; deg += 10) {
            kit.robot().gps(0, 0).headingDeg(deg).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step();
        }
        return kit;
    }

    private static double[] wheels(String command) {
        String[] w = command.split(" ");
        assertThat(w[0]).isEqualTo("DRIVE");
        return new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2])};
    }

    @Test
    void aClearWayGetsNoSuggestion() {
        try (ScenarioKit kit = kit("DRIVE 0.5000 0.5000")) {
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step(3);
            assertThat(kit.suggestions(AVOIDANCE)).hasSize(3).containsOnlyNulls();
            assertThat(kit.decision().winner()).isEqualTo("Driver");
        }
    }

    @Test
    void aStaleScanStopsTheRobotRatherThanDriveBlind() {
        driverCommand = "DRIVE 0.5000 0.5000";
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new Driver()).builtIn(AVOIDANCE).timeStepMs(1000)
                .strategyJson("{\"priorities\": {\"ObstacleAvoidance\": 2, \"Driver\": 1}}").start()) {
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).isNull();
            kit.robot().silent(Sensor.DS);
            kit.step(); // the distance sensors have not been read for a second
            assertThat(kit.suggestion(AVOIDANCE)).isEqualTo("STOP");
        }
    }

    @Test
    void aReadingThatIsNotANumberCountsAsAnObstacleNotAsFreeSpace() {
        try (ScenarioKit kit = kit("DRIVE 0.5000 0.5000")) {
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, FREE, Double.NaN, FREE, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).as("a NaN straight ahead vetoes driving on").isNotNull();
        }
    }

    @Test
    void drivingIntoAnObstacleWithinReachIsReplacedByATurnOnTheSpotTowardTheFreerSide() {
        try (ScenarioKit kit = kit("DRIVE 0.5000 0.5000")) {
            // wall 0.1 m ahead, the right side cluttered, the left side free
            kit.robot().gps(0, 0).headingDeg(0).scan(0.3, 0.3, 0.12, 0.10, 0.10, 0.2, FREE, FREE);
            kit.step();
            double[] w = wheels(kit.suggestion(AVOIDANCE));
            assertThat(w[0]).as("left wheel backwards").isNegative();
            assertThat(w[1]).as("right wheel forwards: turning left on the spot").isPositive();
            assertThat(w[0] + w[1]).isCloseTo(0.0, Offset.offset(1e-9));
            assertThat(kit.decision().winner()).isEqualTo(AVOIDANCE);
        }
    }

    @Test
    void aVetoedTurnKeepsTheDirectionTheDriverWanted() {
        try (ScenarioKit kit = kit("DRIVE 0.3000 0.5000")) { // forward, curving right of... no: left wheel slower, curving left
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, FREE, 0.08, 0.08, FREE, FREE, FREE);
            kit.step();
            double[] w = wheels(kit.suggestion(AVOIDANCE));
            assertThat(w[1]).as("turning left on the spot, as the driver was turning").isPositive();
            assertThat(w[0] + w[1]).isCloseTo(0.0, Offset.offset(1e-9));
        }
    }

    @Test
    void anObstacleBesideTheBodyOrBeyondTheBrakingReachIsLeftToTheDriver() {
        try (ScenarioKit kit = kit("DRIVE 0.5000 0.5000")) {
            // a corridor: walls 0.05 m from the rim on both sides, the way ahead clear
            kit.robot().gps(0, 0).headingDeg(0).scan(0.05, 0.12, FREE, FREE, FREE, FREE, 0.12, 0.05);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).as("a doorway is no obstacle").isNull();
            // an obstacle 0.4 m ahead: beyond what braking needs at 0.5 m/s
            kit.robot().scan(FREE, FREE, FREE, 0.4, 0.4, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).isNull();
        }
    }

    @Test
    void overCellsTheRaysHaveSeenFreeAVetoedCommandBecomesTheNearestArcThatClearsTheObstacle() {
        try (ScenarioKit kit = mappedKit("DRIVE 0.5000 0.5000")) {
            // a post 0.1 m ahead and to the right (the -20° ray): straight on hits it, curving left slips past
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, 0.10, FREE, FREE, FREE, FREE, FREE);
            kit.step();
            double[] w = wheels(kit.suggestion(AVOIDANCE));
            assertThat(w[0]).as("still driving forward, not turning on the spot").isPositive();
            assertThat(w[1]).as("curving left, away from the post").isGreaterThan(w[0]);
        }
    }

    @Test
    void overCellsNoRayHasSeenAVetoedCommandIsStillATurnOnTheSpot() {
        try (ScenarioKit kit = kit("DRIVE 0.5000 0.5000")) {
            // the same post, but the robot has mapped nothing: an arc it was not asked for could meet an unseen corner
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, 0.10, FREE, FREE, FREE, FREE, FREE);
            kit.step();
            double[] w = wheels(kit.suggestion(AVOIDANCE));
            assertThat(w[0] + w[1]).as("a turn on the spot").isCloseTo(0.0, Offset.offset(1e-9));
        }
    }

    @Test
    void turningOnTheSpotOrStoppingIsNeverVetoed() {
        try (ScenarioKit kit = kit("TURN_LEFT 0.2")) {
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, 0.02, 0.02, 0.02, 0.02, 0.02, 0.02, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).isNull();
        }
    }

    @Test
    void aPillarSeenAMomentAgoStillCountsWhenItSlipsBetweenTwoRays() {
        try (ScenarioKit kit = kit("DRIVE 0.5000 0.5000")) {
            // a pillar seen by the 8° ray, 0.3 m ahead: nothing to do yet
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, FREE, FREE, 0.3, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).isNull();
            // closer, between the rays now: every ray reads free, but the remembered hit is in the way
            kit.robot().gps(0.22, 0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).as("the remembered pillar vetoes driving on").isNotNull();
        }
    }

    @Test
    void aWallClosingInAtAFlankIsNotDrivenInto() {
        try (ScenarioKit kit = kit("DRIVE 0.5000 0.5000")) {
            // a wall beside on the left, closing in as the robot goes on: the rays cannot see it ahead
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, 0.05);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).as("beside, not closing yet").isNull();
            kit.robot().gps(0.016, 0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, 0.04);
            kit.step();
            double[] w = wheels(kit.suggestion(AVOIDANCE));
            assertThat(w[0]).as("turning right on the spot, away from the wall").isPositive();
            assertThat(w[0] + w[1]).isCloseTo(0.0, Offset.offset(1e-9));
        }
    }

    @Test
    void turningTowardAFlankThatIsTooCloseIsVetoed() {
        try (ScenarioKit kit = kit("DRIVE 0.1000 0.5000")) { // curving hard left
            kit.robot().gps(0, 0).headingDeg(0).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, 0.03);
            kit.step();
            assertThat(kit.suggestion(AVOIDANCE)).isNotNull();
            assertThat(wheels(kit.suggestion(AVOIDANCE))[0]).as("away from it: right").isPositive();
        }
    }
}
