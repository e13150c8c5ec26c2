package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.scenario.battery.BatteryMonitorScenario;

/** Scenario 4 alone: BatteryMonitor sends the robot to recharge only when it must. */
class BatteryMonitorScenarioTest {

    private static Suggestion suggestion(RobotTablesFixture f) {
        return f.engine.memory().commandArray().get(f.engine.memory().slotOf(BatteryMonitorScenario.NAME));
    }

    private static boolean queued(RobotTablesFixture f, String ruleName) {
        return f.engine.nextQueue().stream().map(Rule::name).anyMatch(ruleName::equals);
    }

    /** Drives the robot 2 m along +x, draining {@code pctPerMetre}, as the engine would see it. */
    private static long drive(RobotTablesFixture f, long t, double fromX, double pctStart, double pctPerMetre) throws Exception {
        for (int i = 0; i <= 20; i++) {
            double x = fromX + i * 0.1;
            f.gps(t, x, 0);
            f.heading(t, 0);
            f.battery(t, pctStart - i * 0.1 * pctPerMetre, false);
            f.iterate(1);
            t += 32;
        }
        return t;
    }

    @Test
    void aFullBatteryWithAShortTripKeepsMonitoring() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("BatteryMonitor")) {
            f.station(-2, 0, 100);
            f.checkpoint(0, 3, 0);
            f.checkpoint(1, 3, 3);
            f.iterate(2);
            drive(f, 0, 0, 100, 1.0);
            assertThat(queued(f, "BatteryMonitor")).isTrue();
            assertThat(suggestion(f)).isNull();
        }
    }

    @Test
    void whenTheNextCheckpointAndTheWayBackCostMoreThanIsLeftItGoesToRechargeAndCharges() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("BatteryMonitor")) {
            f.station(-2, 0, 100);
            f.checkpoint(0, 8, 0);
            f.checkpoint(1, 8, 3);
            f.iterate(2);
            // 2 %/m learnt over 2 m; from x=2: 6 m to the checkpoint + 10 m back = 16 m × 2 × 1.4 + 5 = 49.8 % > 30 %
            long t = drive(f, 0, 0, 34, 2.0);
            assertThat(queued(f, "MoveToRecharge")).isTrue();
            f.iterate(1);
            assertThat(suggestion(f).command()).startsWith("DRIVE");
            // at the station: charge until the battery_recharged level
            f.gps(t, -2, 0.05);
            f.battery(t, 20, false);
            f.iterate(1);
            assertThat(suggestion(f).command()).isEqualTo("RECHARGE");
            f.battery(t + 32, 99.8, true);
            f.iterate(1);
            assertThat(queued(f, "BatteryMonitor")).isTrue();
            assertThat(queued(f, "MoveToRecharge")).isFalse();
        }
    }

    @Test
    void beforeTheDrainIsMeasuredOnlyThePointOfNoReturnSendsItBack() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("BatteryMonitor")) {
            f.station(-2, 0, 100);
            f.checkpoint(0, 8, 0);
            f.iterate(2);
            f.gps(0, 0, 0);
            f.battery(0, 20, false); // far from enough for the trip, but enough to reach the station
            f.iterate(1);
            assertThat(queued(f, "MoveToRecharge")).isFalse();
            f.gps(32, 3, 0);
            f.battery(32, 12, false); // prior 2 %/m × 1.4 × 5 m + 5 = 19 % > 12 %: turn back now
            f.iterate(1);
            assertThat(queued(f, "MoveToRecharge")).isTrue();
        }
    }
}
