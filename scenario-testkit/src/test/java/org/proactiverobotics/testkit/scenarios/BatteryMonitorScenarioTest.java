package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.scenario.battery.BatteryMonitorScenario;
import org.proactiverobotics.engine.scenario.battery.MoveToRecharge;
import org.proactiverobotics.testkit.ScenarioKit;

/** Scenario 4 alone: BatteryMonitor sends the robot to recharge only when it must. */
class BatteryMonitorScenarioTest {

    private static final String BATTERY = BatteryMonitorScenario.NAME;

    private static ScenarioKit kit() {
        return ScenarioKit.builder().builtIn(BATTERY).start();
    }

    /** Drives the robot 2 m along +x, one step per 0.1 m, draining {@code pctPerMetre}, as the engine would see it. */
    private static void drive(ScenarioKit kit, double fromX, double pctStart, double pctPerMetre) {
        for (int i = 0; i <= 20; i++) {
            kit.robot().gps(fromX + i * 0.1, 0).headingDeg(0).battery(pctStart - i * 0.1 * pctPerMetre);
            kit.step();
        }
    }

    @Test
    void aFullBatteryWithAShortTripKeepsMonitoring() {
        try (ScenarioKit kit = kit()) {
            kit.mission().station(-2, 0, 100).checkpoint(3, 0).checkpoint(3, 3);
            drive(kit, 0, 100, 1.0);
            assertThat(kit.scheduled()).contains("BatteryMonitor/BatteryMonitor");
            assertThat(kit.suggestions(BATTERY)).containsOnlyNulls();
        }
    }

    @Test
    void whenTheNextCheckpointAndTheWayBackCostMoreThanIsLeftItGoesToRechargeAndCharges() {
        try (ScenarioKit kit = kit()) {
            kit.mission().station(-2, 0, 100).checkpoint(8, 0).checkpoint(8, 3);
            // 2 %/m learnt over 2 m; from x=2: 6 m to the checkpoint + 10 m back = 16 m × 2 × 1.4 + 5 = 49.8 % > 30 %
            drive(kit, 0, 34, 2.0);
            assertThat(kit.scheduled()).contains("BatteryMonitor/MoveToRecharge");
            kit.step();
            assertThat(kit.suggestion(BATTERY)).startsWith("DRIVE");
            // at the station: charge until the battery_recharged level
            kit.robot().gps(-2, 0.05).battery(20);
            kit.step();
            assertThat(kit.suggestion(BATTERY)).isEqualTo("RECHARGE");
            kit.robot().battery(99.8, true);
            kit.step();
            assertThat(kit.scheduled()).contains("BatteryMonitor/BatteryMonitor").doesNotContain("BatteryMonitor/MoveToRecharge");
        }
    }

    @Test
    void aChargingRobotKeepsChargingWhateverItsGpsSays() {
        try (ScenarioKit kit = kit()) {
            kit.mission().station(-2, 0, 100).checkpoint(8, 0).checkpoint(8, 3);
            drive(kit, 0, 34, 2.0);
            kit.step();
            kit.robot().gps(-2, 0.05).battery(20); // arrived
            kit.step();
            assertThat(kit.suggestion(BATTERY)).isEqualTo("RECHARGE");
            // a noisy fix near the station's rim, before and after the battery says it charges: the robot has not moved
            kit.robot().gps(-2, 0.33);
            kit.step();
            assertThat(kit.suggestion(BATTERY)).as("the battery has not had time to say it charges: it stays").isEqualTo("RECHARGE");
            kit.robot().gps(-2, 0.33).battery(21, true);
            kit.step();
            assertThat(kit.suggestion(BATTERY)).as("charging").isEqualTo("RECHARGE");
            // not charging there after all: once the battery has had time to say so, it drives in
            kit.robot().gps(-2, 0.33).battery(21, false);
            kit.step(20);
            assertThat(kit.suggestion(BATTERY)).startsWith("DRIVE");
        }
    }

    @Test
    void beforeTheDrainIsMeasuredOnlyThePointOfNoReturnSendsItBack() {
        try (ScenarioKit kit = kit()) {
            kit.mission().station(-2, 0, 100).checkpoint(8, 0);
            kit.robot().gps(0, 0).battery(20); // far from enough for the trip, but enough to reach the station
            kit.step();
            assertThat(kit.scheduled()).doesNotContain("BatteryMonitor/MoveToRecharge");
            kit.robot().gps(3, 0).battery(12); // prior 2 %/m × 1.4 × 5 m + 5 = 19 % > 12 %: turn back now
            kit.step();
            assertThat(kit.scheduled()).contains("BatteryMonitor/MoveToRecharge");
        }
    }

    @Test
    void aLegNoChargeCouldPromiseIsTakenAndTheRobotTurnsBackAtThePointOfNoReturnWhereverItIs() {
        try (ScenarioKit kit = kit()) {
            // 2 %/m: from the station 42 m out and 42 m back need 240 %: a recharge cannot make this leg certain
            kit.mission().station(-2, 0, 100).checkpoint(40, 0).checkpoint(0, 3);
            drive(kit, 0, 60, 2.0);
            // then round in circles (radius 0.5 m about (1, 0)), 0.1 m and 0.2 % a step, no nearer the checkpoint
            double pct = 56;
            boolean sentBack = false;
            for (int i = 0; pct > 10 && !sentBack; i++) {
                double a = i * 0.2;
                pct -= 0.2;
                kit.robot().gps(1 + 0.5 * Math.cos(a), 0.5 * Math.sin(a)).headingDeg(Math.toDegrees(a) + 90).battery(pct);
                kit.step();
                sentBack = kit.scheduled().contains("BatteryMonitor/MoveToRecharge");
                // the way back is 2.5 to 3.5 m: 2 %/m × 1.4 × 3.5 m + 5 = 14.8 % at most
                assertThat(sentBack).as("sent back at %.1f %%", pct).isEqualTo(sentBack && pct < 15);
            }
            assertThat(pct).as("sent back by the point of no return, 2 %%/m × 1.4 × 2.5 m + 5 = 12 %% (less what the estimate has yet to learn)").isGreaterThan(10.5);
            assertThat(kit.scheduled()).contains("BatteryMonitor/MoveToRecharge");
        }
    }

    /** A monitor in a world shared with other robots, alone or not: the same rules but where {@code SharedWorld} says. */
    private static ScenarioKit kit(boolean shared) {
        ScenarioKit.Builder b = ScenarioKit.builder().builtIn(BATTERY);
        return (shared ? b.sharedWorld() : b).start();
    }

    /**
     * On its way to the station (sent there at x = 2 with 30 %, 2 %/m learnt), the robot is put at {@code x} with {@code pct} left.
     *
     * @return what the battery scenario suggests there
     */
    private static String onTheWayToTheStationAt(boolean shared, double x, double pct) {
        try (ScenarioKit kit = kit(shared)) {
            sentToTheStation(kit);
            assertThat(kit.scheduled()).contains("BatteryMonitor/MoveToRecharge");
            kit.robot().gps(x, 0).headingDeg(180).battery(pct);
            kit.step(2);
            return kit.suggestion(BATTERY);
        }
    }

    @Test
    void amongOtherRobotsAWayToTheStationLongerThanWhatIsLeftCanDriveIsNotDrivenFlat() {
        // from x = 2 (30 %) to 5 with 12 % left: 22 % over 5 m learnt, 4.4 %/m; 6.8 m to the station need 30 %: stopped it
        // keeps its charge (a way blocked by others may open)
        assertThat(onTheWayToTheStationAt(true, 5, 12)).isEqualTo("STOP");
        assertThat(onTheWayToTheStationAt(false, 5, 12)).as("a lone robot's trip as it always was").startsWith("DRIVE");
        // to x = -0.5 with 20 %: 3.1 %/m, 1.3 m need 4 %: on it drives
        assertThat(onTheWayToTheStationAt(true, -0.5, 20)).startsWith("DRIVE");
    }

    /**
     * Past the point of no return on the last leg (the station 10 m behind), the last checkpoint 2.4 m ahead: the
     * robot goes on for it from x = 0.8 with {@code startPct} (0.1 m and 0.2 % a step), then circles short of it (a
     * route through a wall the map let go), 0.06 m and 0.12 % a step.
     *
     * @return the battery left when the monitor sent it to the station, percent (0: not before 5 %)
     */
    private static double sentBackCirclingShortOfTheLastCheckpoint(boolean shared, double startPct, boolean whileApproaching) {
        try (ScenarioKit kit = kit(shared)) {
            kit.mission().station(-10, 0, 100).checkpoint(3.2, 0);
            // from x = 0.8 with 30 %: the way back needs 2 %/m x 1.25 x 10.8 m + 5 = 32 %, the checkpoint 11 %: on for it
            for (int i = 0; i <= 20; i++) {
                double pct = startPct - i * 0.2;
                kit.robot().gps(0.8 + i * 0.1, 0).headingDeg(0).battery(pct);
                kit.step();
                if (kit.scheduled().contains("BatteryMonitor/MoveToRecharge")) {
                    return whileApproaching ? pct : 0;
                }
            }
            if (whileApproaching) {
                return 0;
            }
            double pct = startPct - 4;
            for (int i = 0; pct > 5; i++) {
                double a = i * 0.2;
                pct -= 0.12;
                kit.robot().gps(2.5 + 0.3 * Math.cos(a), 0.3 * Math.sin(a)).headingDeg(Math.toDegrees(a) + 90).battery(pct);
                kit.step();
                if (kit.scheduled().contains("BatteryMonitor/MoveToRecharge")) {
                    return pct;
                }
            }
            return 0;
        }
    }

    @Test
    void amongOtherRobotsGoingOnForTheLastCheckpointPastTheWayBackEndsWhileTheStationIsStillWithinReach() {
        // a lone robot's monitor as it always was: on while what is left covers the checkpoint (7 to 9 % from the circle)
        assertThat(sentBackCirclingShortOfTheLastCheckpoint(false, 30, true)).as("a lone robot goes on for it").isZero();
        assertThat(sentBackCirclingShortOfTheLastCheckpoint(false, 30, false)).isBetween(5.0, 9.5);
        // issue 34: among others, having set out with the station within reach at its least cost (2 %/m x 10.8 m + 5 =
        // 26.6 % at x = 0.8, with 30 %), it goes on only while it still is: by x = 1.65, 28.3 % = 2 %/m x 11.65 m + 5,
        // the station then (its budget, 6 %, would have sent it at 24 %, with less than the way back costs)
        assertThat(sentBackCirclingShortOfTheLastCheckpoint(true, 30, true)).isBetween(27.5, 29.0);
        // set out with less (25 %), the station already out of reach: on until what finishing was to cost, 2 %/m x 1.25 x
        // 2.4 m = 6 %, is spent, by 19 %
        assertThat(sentBackCirclingShortOfTheLastCheckpoint(true, 25, true)).as("goes on for it").isZero();
        assertThat(sentBackCirclingShortOfTheLastCheckpoint(true, 25, false)).isBetween(18.5, 19.0);
    }

    /** The station at x = -2, checkpoints at (8, 0) and (8, 3): driven from the origin with 34 %, 2 %/m, it is sent there at x = 2. */
    private static void sentToTheStation(ScenarioKit kit) {
        kit.mission().station(-2, 0, 100).checkpoint(8, 0).checkpoint(8, 3);
        drive(kit, 0, 34, 2.0);
    }

    /** The robot put at {@code x} with {@code pct} left stands there for {@code ms}, the battery's command winning each step. */
    private static void standAt(ScenarioKit kit, double x, double pct, int ms) {
        kit.robot().gps(x, 0).headingDeg(180).battery(pct);
        for (int i = 0; i < ms / 32; i++) {
            kit.step();
            // the decision scenario is not in the kit: what it would record, the battery's suggestion won
            kit.memory().values().put(SharedMemory.LAST_DECISION, BATTERY + " " + kit.suggestion(BATTERY));
        }
    }

    /**
     * Sent to the station among other robots (as {@link #onTheWayToTheStationAt}), the robot is put at {@code x} with
     * {@code pct} left and stands there for 10 s, the battery's command winning each step.
     *
     * @return how many places the route to the station closed meanwhile
     */
    private static int placesClosedStandingAt(double x, double pct) {
        try (ScenarioKit kit = kit(true)) {
            sentToTheStation(kit);
            standAt(kit, x, pct, 10_000);
            return kit.engine().engine().nextQueue().stream().filter(MoveToRecharge.class::isInstance)
                    .map(MoveToRecharge.class::cast).findFirst().orElseThrow().closedPlaces().size();
        }
    }

    /*
     * Issue 34: stopped by its own rule for a way longer than the battery, the robot's route follower counted the time
     * as a drive without progress and closed a place round the standing robot every 5 s, the way ever longer (rooms-029
     * robot 2, corridors-021 robot 3, corridors-025 robot 2 stood so till the time limit).
     */
    @Test
    void amongOtherRobotsStandingForTheBatteryIsNoStallOnTheWayToTheStation() {
        assertThat(placesClosedStandingAt(5, 12)).as("stopped by its own rule: no place closed").isZero();
        // driving for the way and getting nowhere still is a stall: a place closed after 5 s
        assertThat(placesClosedStandingAt(-0.5, 20)).isPositive();
    }

    /**
     * Sent to the station among other robots (as {@link #onTheWayToTheStationAt}), the robot is put at {@code x} with
     * {@code pct} left and stands there for {@code seconds}, the battery's command winning each step.
     *
     * @return how often the battery scenario asked the mapping to look again ({@code SharedWorld.LOOK_AGAIN}, 0: never)
     */
    private static int looksAgainStandingAt(double x, double pct, int seconds) throws SQLException {
        return looksAgainStandingAt(x, pct, seconds, false);
    }

    /** As above; {@code done}: every checkpoint reached before it stands (a robot that is done, sent to charge). */
    private static int looksAgainStandingAt(double x, double pct, int seconds, boolean done) throws SQLException {
        try (ScenarioKit kit = kit(true)) {
            sentToTheStation(kit);
            if (done) {
                try (Connection c = kit.database().getConnection(); Statement st = c.createStatement()) {
                    st.executeUpdate("UPDATE checkpoints SET reached = TRUE WHERE robot_id = " + ScenarioKit.ROBOT_ID);
                }
            }
            standAt(kit, x, pct, seconds * 1000);
            return SharedWorld.lookAgainAsked(kit.memory().values());
        }
    }

    /*
     * Issue 34: held for the battery, robots stood till the time limit with 15 to 26 % left (corridors 14, 16 and 29 of
     * the generated worlds of four robots): the short way was shut by robots that had since left, or drawn so on the
     * map. Held 5 s, the robot asks its map to let go of what moved in, at most 3 times a trip, while a checkpoint
     * waits (116 of 120 runs, 115 before; no robot below 5 %).
     */
    @Test
    void amongOtherRobotsARobotHeldForTheBatteryLooksAgainEvery5SecondsAtMost3Times() throws SQLException {
        assertThat(looksAgainStandingAt(5, 12, 4)).as("held 4 s: not yet").isZero();
        assertThat(looksAgainStandingAt(5, 12, 6)).as("held 6 s: once").isEqualTo(1);
        assertThat(looksAgainStandingAt(5, 12, 30)).as("held 30 s: three times, no more").isEqualTo(3);
        assertThat(looksAgainStandingAt(-0.5, 20, 30)).as("not held (the way within what is left): never").isZero();
        // a robot that is done loses nothing standing: one that looked again drove a way that grew, down to 1.2 %
        assertThat(looksAgainStandingAt(5, 12, 30, true)).as("done, held 30 s: never").isZero();
    }

    /**
     * Drives away from the station (at x = -2) along +x from the origin, 0.1 m and 0.2 % a step from 22 %, on a map
     * with nothing seen: the way back runs through cells no ray has seen.
     *
     * @return the battery left when the monitor sent the robot to the station, percent (0: not by x = 6)
     */
    private static double sentBackDrivingAwayOverUnseenCells(boolean shared) {
        try (ScenarioKit kit = kit(shared)) {
            kit.mission().station(-2, 0, 100).checkpoint(40, 0);
            for (int i = 0; i <= 60; i++) {
                double pct = 22 - i * 0.2;
                kit.robot().gps(i * 0.1, 0).headingDeg(0).battery(pct);
                kit.step();
                if (kit.scheduled().contains("BatteryMonitor/MoveToRecharge")) {
                    return pct;
                }
            }
            return 0;
        }
    }

    /*
     * Issue 34: among other robots a way back through unseen cells turned out longer than planned (walls, other
     * robots on it): robots turned back with 22 to 26 % and then stood short of the station, what was left less than
     * the way found. Such a way is counted 1.5 times there, not 1.25.
     */
    @Test
    void amongOtherRobotsAWayBackThroughUnseenCellsIsCountedLonger() {
        // 2 %/m: a lone robot turns back where 2 x 1.25 x the way + 5 % is what is left (about x = 2.7, 16.6 %)
        double lone = sentBackDrivingAwayOverUnseenCells(false);
        assertThat(lone).isBetween(16.0, 17.0);
        // among others where 2 x 1.5 x the way + 5 % is (about x = 2.2, 17.6 %): sooner, with more left
        assertThat(sentBackDrivingAwayOverUnseenCells(true)).isBetween(lone + 0.8, 18.5);
    }
}
