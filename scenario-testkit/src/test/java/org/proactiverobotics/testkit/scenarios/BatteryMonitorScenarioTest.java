package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.scenario.battery.BatteryMonitorScenario;
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
}
