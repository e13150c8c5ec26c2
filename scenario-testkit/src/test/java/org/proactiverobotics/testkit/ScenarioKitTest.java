package org.proactiverobotics.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.Part;
import org.proactiverobotics.engine.robot.PluginException;
import org.proactiverobotics.engine.robot.StrategyException;
import org.proactiverobotics.engine.scenario.failsafe.WatchFailures;
import org.proactiverobotics.engine.tables.Sensor;

/** The kit itself, on a small scenario of a user's own (SpeedGovernor). */
class ScenarioKitTest {

    private static final double FREE = ScriptedRobot.SENSOR_RANGE_M;
    private static final double[] CLEAR = {FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE};
    /** An obstacle 0.3 m straight ahead. */
    private static final double[] NEAR = {FREE, FREE, FREE, 0.3, 0.3, FREE, FREE, FREE};
    /** An obstacle 0.05 m ahead: within braking reach, so the built-in avoidance vetoes driving on too. */
    private static final double[] CLOSE = {FREE, FREE, 0.1, 0.05, 0.05, 0.1, FREE, FREE};
    private static final String GOVERNOR = SpeedGovernorScenario.NAME;

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void itSuggestsStepByStepAndItsSuggestionIsDecidedThenSent(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).database(db.dataSource()).start()) {
            assertThat(kit.scheduled()).as("started: its rule runs in the first step").containsExactly(
                    "Localisation/EstimatePose", "SpeedGovernor/Govern", "DecisionMaking/ReadRobotCommands");
            kit.robot().gps(0.0, -4.0).headingDeg(90).scan(CLEAR).battery(80);
            kit.step();
            assertThat(kit.suggestion(GOVERNOR)).isNull();
            kit.robot().scan(NEAR);
            kit.step();
            assertThat(kit.suggestion(GOVERNOR)).isEqualTo("FORWARD 0.1");
            assertThat(kit.decision().winner()).isEqualTo(GOVERNOR);
            assertThat(kit.decision().suggestions()).containsExactly(Map.entry(GOVERNOR, "FORWARD 0.1"));
            kit.robot().scan(CLEAR);
            kit.step();

            assertThat(kit.suggestions(GOVERNOR)).containsExactly(null, "FORWARD 0.1", null);
            assertThat(kit.decisions()).extracting(Decision::command).containsExactly("STOP", "FORWARD 0.1", "STOP");
            // a decision is sent in the next iteration
            assertThat(kit.sentCommands()).containsExactly("STOP", "FORWARD 0.1");
            assertThat(kit.sent()).last().satisfies(s -> {
                assertThat(s.scenario()).isEqualTo(GOVERNOR);
                assertThat(s.simTimeMs()).as("the GPS time of the step that sent it").isEqualTo(64);
            });
            assertThat(kit.scheduled()).contains("SpeedGovernor/Govern");
            assertThat(kit.failures()).isEmpty();
            assertThat(kit.simTimeMs()).isEqualTo(96);
            assertThat(kit.requestedSensors()).as("no data acquisition: nobody asks").isEmpty();
        }
    }

    @Test
    void aScanThatStopsComingGoesStaleAndTheRobotIsStopped() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).start()) {
            kit.robot().gps(0, 0).scan(CLEAR);
            kit.step();
            kit.robot().silent(Sensor.DS);
            kit.step(4); // the scan of t=0 is 32, 64, 96 then 128 ms behind the GPS
            assertThat(kit.suggestions(GOVERNOR)).containsExactly(null, null, null, null, "STOP");
            kit.robot().scan(CLEAR); // publishing again
            kit.step();
            assertThat(kit.suggestion(GOVERNOR)).isNull();
        }
    }

    @Test
    void withoutAnyScanItStopsAtOnce() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).start()) {
            kit.robot().gps(0, 0);
            kit.step();
            assertThat(kit.suggestion(GOVERNOR)).isEqualTo("STOP");
        }
    }

    @Test
    void aSilentSensorLeavesTheDataAcquisitionsRequestPending() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).withDataAcquisition().start()) {
            kit.robot().gps(0, 0).headingDeg(0).scan(CLEAR).battery(90).odometry(0, 0);
            kit.step();
            assertThat(kit.requestedSensors()).containsExactly("GPS", "DS", "IU", "ODOMETRY");
            kit.robot().silent(Sensor.DS);
            kit.step(3);
            assertThat(kit.requestedSensors()).as("answered every step but the scan's, asked once")
                    .containsExactly("DS", "GPS", "IU", "ODOMETRY");
        }
    }

    @Test
    void garbageIsWrittenAsIsAndANotANumberAheadCountsAsAnObstacle() throws Exception {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).start()) {
            kit.robot().gps(0, 0).scan(-1, FREE, FREE, Double.NaN, FREE, FREE, FREE, FREE);
            kit.step();
            assertThat(kit.suggestion(GOVERNOR)).isEqualTo("FORWARD 0.1");
            try (var c = kit.database().getConnection(); var s = c.createStatement();
                 var rs = s.executeQuery("SELECT distance_m FROM distance_sensor_data ORDER BY sensor_index")) {
                rs.next();
                assertThat(rs.getDouble(1)).isEqualTo(-1.0);
                rs.next();
                rs.next();
                rs.next();
                assertThat(rs.getDouble(1)).isNaN();
            }
        }
    }

    @Test
    void aPartThatThrowsIsItsFailureAndWithoutAFailSafeTheScenarioIsGone() {
        ScanFault fault = new ScanFault();
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).faults(fault::wrap).start()) {
            kit.robot().gps(0, 0).scan(NEAR);
            kit.step();
            fault.on();
            kit.step();
            assertThat(kit.failures()).singleElement().satisfies(f -> {
                assertThat(f.scenario()).isEqualTo(GOVERNOR);
                assertThat(f.rule()).isEqualTo("Govern");
                assertThat(f.part()).isEqualTo(Part.CONDITION_DATA_ACQUISITION);
                assertThat(f.message()).contains("the scan cannot be read");
            });
            assertThat(kit.suggestion(GOVERNOR)).isNull();
            assertThat(kit.scheduled()).doesNotContain("SpeedGovernor/Govern");
            fault.off();
            kit.step(3);
            assertThat(kit.failures()).isEmpty();
            assertThat(kit.suggestions(GOVERNOR)).containsExactly("FORWARD 0.1", null, null, null, null);
            assertThat(kit.sentCommands()).last().isEqualTo("STOP");
        }
    }

    @Test
    void withTheFailSafeAFailedScenarioIsRestarted() {
        ScanFault fault = new ScanFault();
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).withFailSafe()
                .faults(fault::wrap).start()) {
            kit.robot().gps(0, 0).scan(NEAR);
            kit.step();
            fault.on();
            kit.step();
            fault.off();
            kit.step((int) WatchFailures.RESTART_AFTER_ITERATIONS + 2);
            assertThat(kit.scheduled()).contains("SpeedGovernor/Govern");
            assertThat(kit.suggestion(GOVERNOR)).isEqualTo("FORWARD 0.1");
            assertThat(kit.memory().values().get(WatchFailures.RECORD_PREFIX + GOVERNOR)).startsWith("back after 1 restart(s)");
        }
    }

    @Test
    void byDefaultYourScenarioRanksAboveTheBuiltInOnes() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).builtIn("ObstacleAvoidance").start()) {
            kit.robot().gps(0, 0).headingDeg(0).scan(CLOSE);
            kit.step();
            assertThat(kit.decision().suggestions()).containsOnlyKeys(GOVERNOR, "ObstacleAvoidance");
            assertThat(kit.decision().winner()).isEqualTo(GOVERNOR);
        }
    }

    @Test
    void aStrategyThatRanksItFirstMakesItWinAndLastMakesItLose() {
        assertThat(winnerUnder("{\"priorities\": {\"SpeedGovernor\": 10, \"ObstacleAvoidance\": 5}}"))
                .containsExactly(GOVERNOR, "FORWARD 0.1");
        List<String> lost = winnerUnder("{\"priorities\": {\"SpeedGovernor\": 1, \"ObstacleAvoidance\": 5}}");
        assertThat(lost.get(0)).isEqualTo("ObstacleAvoidance");
        assertThat(lost.get(1)).startsWith("DRIVE");
    }

    /** @return the winner of a step before an obstacle, then the command sent for it */
    private static List<String> winnerUnder(String strategyJson) {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).builtIn("ObstacleAvoidance")
                .strategyJson(strategyJson).start()) {
            kit.robot().gps(0, 0).headingDeg(0).scan(CLOSE);
            kit.step();
            assertThat(kit.decision().suggestions()).containsKeys(GOVERNOR, "ObstacleAvoidance");
            String winner = kit.decision().winner();
            kit.step();
            return List.of(winner, kit.sentCommands().get(kit.sentCommands().size() - 1));
        }
    }

    @Test
    void misuseIsRefusedNamingWhatIsKnown() {
        assertThatThrownBy(() -> ScenarioKit.builder().builtIn("ObstacleAvoidence"))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("ObstacleAvoidence")
                .hasMessageContaining("ObstacleAvoidance");
        assertThatThrownBy(() -> ScenarioKit.builder().strategyJson("{\"priorities\": {\"SpeedGovernor\": 1.5}}"))
                .isInstanceOf(StrategyException.class).hasMessageContaining("priorities.SpeedGovernor");
        assertThatThrownBy(() -> ScenarioKit.builder().scenario(new SpeedGovernorScenario())
                .strategyJson("{\"priorities\": {\"SpeedGovernr\": 1}}").start())
                .isInstanceOf(StrategyException.class).hasMessageContaining("SpeedGovernr");
        assertThatThrownBy(() -> ScenarioKit.builder().scenario(new SpeedGovernorScenario())
                .scenario(new SpeedGovernorScenario()).start())
                .isInstanceOf(PluginException.class).hasMessageContaining(GOVERNOR);
        assertThatThrownBy(() -> ScenarioKit.builder().timeStepMs(0)).isInstanceOf(IllegalArgumentException.class);
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpeedGovernorScenario()).start()) {
            assertThatThrownBy(() -> kit.suggestion("SpeedGovernr")).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining(GOVERNOR);
            assertThatThrownBy(() -> kit.robot().scan(1, 1, 1)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("8 distance sensors");
            assertThat(kit.suggestion(GOVERNOR)).as("before the first step").isNull();
            assertThat(kit.decision()).isNull();
            kit.close();
            assertThatThrownBy(kit::step).isInstanceOf(ScenarioKitException.class).hasMessageContaining("closed");
        }
    }

    @Test
    void theMissionRowsAreWhatTheScenariosRead() {
        try (ScenarioKit kit = ScenarioKit.builder().builtIn("ReachDestination").start()) {
            kit.mission().checkpoint(0.0, 1.0).checkpoint(2.0, 1.0, 0.5).station(-3, 0, 100);
            assertThat(kit.engine().tables().mission().checkpoints())
                    .extracting(c -> c.seq() + ":" + c.xM() + "," + c.yM() + " r" + c.radiusM())
                    .containsExactly("0:0.0,1.0 r0.25", "1:2.0,1.0 r0.5");
            assertThat(kit.engine().tables().mission().rechargeStation()).hasValueSatisfying(
                    s -> assertThat(Arrays.asList(s.xM(), s.yM(), s.radiusM())).containsExactly(-3.0, 0.0, 0.35));
            assertThat(kit.engine().tables().mission().rechargeLevelPct()).hasValue(100.0);
            kit.robot().gps(0.0, 0.95).headingDeg(90);
            kit.step(2);
            assertThat(kit.reachedCheckpoints()).containsExactly(0);
        }
    }
}
