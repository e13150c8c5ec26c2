package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.scenario.battery.BatteryMonitorScenario;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.scenario.traffic.GiveWay;
import org.proactiverobotics.engine.scenario.traffic.YieldScenario;
import org.proactiverobotics.testkit.ScenarioKit;
import org.proactiverobotics.testkit.ScriptedRobot;

/** The traffic scenario with the scenarios it gives way for: each rule, with scripted readings. */
class YieldScenarioTest {

    private static final String YIELD = YieldScenario.NAME;
    private static final String DESTINATION = ReachDestinationScenario.NAME;
    private static final String BATTERY = BatteryMonitorScenario.NAME;
    /** 32 ms steps in a second. */
    private static final int SECOND = 32;

    private static ScenarioKit kit(String... builtIns) {
        return ScenarioKit.builder().sharedWorld().builtIn(builtIns).builtIn(YIELD).start();
    }

    /** The front rays (±8°, ±20°) read d from the rim, the others nothing. */
    private static double[] ahead(double d) {
        return new double[] {1, 1, d, d, d, d, 1, 1};
    }

    /** In a 0.6 m corridor: the rays at ±90° read 0.18 m, ±45° 0.25 m; the front rays d. */
    private static double[] inCorridor(double d) {
        return new double[] {0.18, 0.25, d, d, d, d, 0.25, 0.18};
    }

    @Test
    void somethingComingHeadOnInACorridorMakesItBackOutThenWaitATimeItsIdSetsThenGoOn() {
        try (ScenarioKit kit = kit(DESTINATION)) {
            kit.mission().checkpoint(3, 0);
            kit.robot().gps(0, 0).headingDeg(0).scan(inCorridor(1));
            kit.step(5);
            assertThat(kit.decision().winner()).isEqualTo(DESTINATION);
            assertThat(kit.suggestion(YIELD)).as("the way clear: it says nothing").isNull();
            // something 0.65 m ahead comes 3 cm nearer each step while this robot stands still
            for (int s = 0; s < 5; s++) { // seen at 0.65 m, coming once 7 cm nearer (0.56 m), given way to at the next step
                kit.robot().scan(inCorridor(0.65 - 0.03 * s));
                kit.step();
            }
            assertThat(kit.decision().winner()).isEqualTo(YIELD);
            assertThat(kit.decision().command()).as("backs off, straight (the walls as far on both sides)")
                    .isEqualTo("DRIVE -0.3000 -0.3000");
            kit.robot().scan(inCorridor(0.5)); // it stopped there; still between the walls: backs on
            kit.step(SECOND * 3);
            assertThat(kit.decision().command()).as("between two walls after 3 s: still backing").startsWith("DRIVE -0.3");
            kit.robot().scan(ahead(0.5)); // out of the corridor: both sides open
            kit.step(2);
            assertThat(kit.decision().command()).as("out in the open, it waits").isEqualTo("STOP");
            assertThat(kit.decision().winner()).isEqualTo(YIELD);
            kit.step((int) (GiveWay.waitMs(ScenarioKit.ROBOT_ID) / 32) + 2);
            assertThat(kit.suggestion(YIELD)).as("waited its turn: hands back").isNull();
            assertThat(kit.decision().winner()).isEqualTo(DESTINATION);
        }
    }

    @Test
    void inTheOpenItStopsForWhatComesInsteadOfBackingOff() {
        try (ScenarioKit kit = kit(DESTINATION)) {
            kit.mission().checkpoint(3, 0);
            kit.robot().gps(0, 0).headingDeg(0).scan(ahead(1));
            kit.step(3);
            for (int s = 0; s < 5; s++) { // seen at 0.65 m, coming once 7 cm nearer (0.56 m), given way to at the next step
                kit.robot().scan(ahead(0.65 - 0.03 * s));
                kit.step();
            }
            assertThat(kit.decision().winner()).isEqualTo(YIELD);
            assertThat(kit.decision().command()).isEqualTo("STOP");
            int waitSteps = (int) (GiveWay.waitMs(ScenarioKit.ROBOT_ID) / 32) - 2; // robot 1 waits 0.8 s
            kit.step(waitSteps);
            assertThat(kit.decisions().subList(kit.decisions().size() - waitSteps, kit.decisions().size()))
                    .as("stopped where it is, no backing off").allMatch(d -> d.command().equals("STOP"));
        }
    }

    @Test
    void aWallItDrivesAtIsNoReasonToGiveWay() {
        try (ScenarioKit kit = kit(DESTINATION)) {
            kit.mission().checkpoint(3, 0);
            // the robot drives 1.6 cm a step toward a wall; the wall draws nearer exactly as fast
            for (int s = 0; s < 20; s++) {
                kit.robot().gps(0.016 * s, 0).headingDeg(0).scan(ahead(0.69 - 0.016 * s));
                kit.step();
            }
            assertThat(kit.suggestions(YIELD)).containsOnlyNulls();
        }
    }

    /**
     * What the rays read of a round pillar (and nothing else), from the rim of a robot of 0.12 m: the ray's first
     * crossing of the circle, or the 1 m range.
     */
    private static double[] pillar(double x, double y, double yawRad, double cx, double cy, double radiusM) {
        double[] d = new double[ScriptedRobot.SENSOR_ANGLES_DEG.length];
        for (int k = 0; k < d.length; k++) {
            double a = yawRad + Math.toRadians(ScriptedRobot.SENSOR_ANGLES_DEG[k]);
            double along = (cx - x) * Math.cos(a) + (cy - y) * Math.sin(a);
            double disc = along * along - ((cx - x) * (cx - x) + (cy - y) * (cy - y) - radiusM * radiusM);
            double t = disc >= 0 ? along - Math.sqrt(disc) : Double.POSITIVE_INFINITY;
            d[k] = t > 0.12 ? Math.min(1.0, Math.round((t - 0.12) * 1000) / 1000.0) : 1.0;
        }
        return d;
    }

    @Test
    void aPillarsEdgeTheRaysSweepWhileTheRobotTurnsIsNoReasonToGiveWay() {
        try (ScenarioKit kit = kit(DESTINATION)) {
            kit.mission().checkpoint(3, 0);
            // a pillar of 6 cm, 0.55 m ahead; the robot drives at 0.5 m/s and turns at 0.6 rad/s, so its front rays
            // sweep over the pillar's edge: the place 4 cm behind a hit near the edge is outside the pillar, and an
            // earlier ray passed there (before, it gave way at the third step)
            double x = 0;
            double y = 0;
            double yaw = 0;
            for (int s = 0; s < 20; s++) {
                kit.robot().gps(x, y).headingRad(yaw).scan(pillar(x, y, yaw, 0.55, 0.0, 0.06));
                kit.step();
                x += 0.016 * Math.cos(yaw);
                y += 0.016 * Math.sin(yaw);
                yaw += 0.6 * 0.032;
            }
            assertThat(kit.suggestions(YIELD)).containsOnlyNulls();
        }
    }

    @Test
    void somethingThatMovesInAndStandsStillIsNoReasonToGiveWay() {
        try (ScenarioKit kit = kit(DESTINATION)) {
            kit.mission().checkpoint(3, 0);
            kit.robot().gps(0, 0).headingDeg(0).scan(ahead(1));
            kit.step(3);
            // a robot crosses into the way 0.5 m ahead and stops there: it moved in, but comes no nearer
            // (before, the robot gave way to it at once)
            kit.robot().scan(ahead(0.5));
            kit.step(SECOND);
            assertThat(kit.suggestions(YIELD)).containsOnlyNulls();
        }
    }

    @Test
    void robotsOfDifferentIdsWaitDifferentTimes() {
        List<Long> waits = List.of(GiveWay.waitMs(1), GiveWay.waitMs(2), GiveWay.waitMs(3));
        assertThat(waits).doesNotHaveDuplicates().isSorted();
        assertThat(waits.get(1) - waits.get(0)).as("apart by more than the backing off").isGreaterThan(1_000);
    }

    /** A station 2 m behind and two checkpoints ahead: 2 %/m learnt over 2 m, the next leg and the way back cost more than is left. */
    private static void headForTheStation(ScenarioKit kit) {
        kit.mission().station(-2, 0, 100).checkpoint(8, 0).checkpoint(8, 3);
        for (int i = 0; i <= 20; i++) {
            kit.robot().gps(i * 0.1, 0).headingDeg(0).battery(34 - i * 0.2);
            kit.step();
        }
    }

    @Test
    void aRobotHeadingForATakenStationWaitsNearbyUntilItIsFreeThenDrivesOn() {
        try (ScenarioKit kit = kit(BATTERY)) {
            headForTheStation(kit);
            kit.step();
            assertThat(kit.decision().winner()).isEqualTo(BATTERY);
            // 0.8 m from the station, facing it: something stands on it (the front rays stop 0.18 m short of its centre)
            kit.robot().gps(-1.2, 0).headingDeg(180).scan(ahead(0.5));
            kit.step(3);
            assertThat(kit.decision().winner()).isEqualTo(YIELD);
            assertThat(kit.decision().command()).isEqualTo("STOP");
            kit.step(5 * SECOND); // five seconds: still waiting, where it is
            assertThat(kit.decision().command()).isEqualTo("STOP");
            assertThat(kit.decisions().subList(kit.decisions().size() - 5 * SECOND, kit.decisions().size()))
                    .allMatch(d -> d.winner().equals(YIELD) && d.command().equals("STOP"));
            kit.robot().scan(ahead(1)); // it left
            kit.step(SECOND);
            assertThat(kit.suggestion(YIELD)).isNull();
            assertThat(kit.decision().winner()).isEqualTo(BATTERY);
            assertThat(kit.decision().command()).startsWith("DRIVE");
        }
    }

    @Test
    void aRobotWaitingForAStationThatStaysTakenGoesOnAfterItsLongestWait() {
        try (ScenarioKit kit = kit(BATTERY)) {
            headForTheStation(kit);
            // what takes the station never leaves (robots waiting round a free station see each other so)
            kit.robot().gps(-1.2, 0).headingDeg(180).scan(ahead(0.5));
            kit.step(5 * SECOND);
            assertThat(kit.decision().winner()).isEqualTo(YIELD);
            assertThat(kit.decision().command()).isEqualTo("STOP");
            // robot 1 waits at most 6 s + 0.8 s: then the battery scenario drives it on (before, it waited for good)
            kit.step(2 * SECOND);
            assertThat(kit.suggestion(YIELD)).isNull();
            assertThat(kit.decision().winner()).isEqualTo(BATTERY);
            assertThat(kit.decision().command()).startsWith("DRIVE");
        }
    }

    @Test
    void aWallBehindTheStationDoesNotTakeIt() {
        try (ScenarioKit kit = kit(BATTERY)) {
            headForTheStation(kit);
            kit.robot().gps(-1.2, 0).headingDeg(180).scan(ahead(0.88)); // hits at x = -2.2: beyond the station's centre
            kit.step(10);
            assertThat(kit.suggestions(YIELD)).containsOnlyNulls();
            assertThat(kit.decision().winner()).isEqualTo(BATTERY);
        }
    }

    @Test
    void theDefaultStrategyOfASharedWorldRanksYieldRightBelowTheCollisionMonitor() {
        Strategy s = Strategy.named(Strategy.SAFETY_FIRST).forSharedWorld();
        assertThat(s.priorities()).containsExactly(
                org.assertj.core.api.Assertions.entry("ObstacleAvoidance", 6), org.assertj.core.api.Assertions.entry("Yield", 5),
                org.assertj.core.api.Assertions.entry("BatteryMonitor", 4), org.assertj.core.api.Assertions.entry("ReachDestination", 2));
        assertThat(RobotEngine.startOrderPhrase(true)).isEqualTo(RobotEngine.SHARED_WORLD_ORDER_TEXT);
        assertThat(RobotEngine.startOrderPhrase(false)).as("a lone robot's order is as it was").isEqualTo(RobotEngine.ORDER_TEXT);
    }
}
