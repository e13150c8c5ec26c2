package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;

import org.junit.jupiter.api.Test;

class BatteryAndCheckpointTest {

    private static WorldSpec line(WorldSpec.Battery battery, List<WorldSpec.Checkpoint> checkpoints) {
        WorldSpec base = Worlds.empty(5.0, 0.0, 0.0, 0.0);
        return new WorldSpec("line", 32, 600, 3, base.arena(), base.robot(), List.of(), checkpoints, 0.25,
                new WorldSpec.RechargeStation(0.0, 0.0, 0.35), battery);
    }

    @Test
    void batteryDrainsPerMetreTravelled() {
        Simulation sim = new Simulation(line(new WorldSpec.Battery(100, 2.0, 100, 10), List.of(new WorldSpec.Checkpoint(3, 3))));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 125); // 2 m
        assertThat(sim.robot().battery().getLevelPct()).isCloseTo(96.0, within(1e-9));
        assertThat(sim.groundTruth().minBatteryPct()).isCloseTo(96.0, within(1e-9));
        // Turning in place moves the centre nowhere and costs nothing.
        sim.robot().setWheelSpeeds(-0.5, 0.5);
        Worlds.run(sim, 20);
        assertThat(sim.robot().battery().getLevelPct()).isCloseTo(96.0, within(1e-9));
    }

    @Test
    void aFlatBatteryStopsTheRobot() {
        Simulation sim = new Simulation(line(new WorldSpec.Battery(1.0, 1.0, 100, 10), List.of(new WorldSpec.Checkpoint(3, 3))));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 200); // would be 3.2 m
        assertThat(sim.robot().battery().getLevelPct()).isZero();
        assertThat(sim.groundTruth().distanceM()).isCloseTo(1.0, within(0.02));
        double x = sim.groundTruth().x();
        Worlds.run(sim, 10);
        assertThat(sim.groundTruth().x()).isEqualTo(x);
        assertThat(sim.groundTruth().minBatteryPct()).isZero();
    }

    @Test
    void chargingWorksOnlyAtTheStationAndStopsAtRechargeTo() {
        Simulation sim = new Simulation(line(new WorldSpec.Battery(50, 1.0, 80, 10), List.of(new WorldSpec.Checkpoint(3, 3))));
        Battery battery = sim.robot().battery();
        assertThat(battery.isAtStation()).isTrue();
        assertThat(battery.startCharging()).isTrue();
        Worlds.run(sim, 50); // 1.6 s at 10 %/s
        assertThat(battery.getLevelPct()).isCloseTo(66.0, within(1e-9));
        Worlds.run(sim, 100);
        assertThat(battery.getLevelPct()).isEqualTo(80.0);
        assertThat(battery.isCharging()).isFalse();
        assertThat(battery.startCharging()).isFalse(); // already at rechargeTo
        assertThat(sim.groundTruth().recharges()).isEqualTo(1);

        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 125); // 2 m away
        assertThat(battery.isAtStation()).isFalse();
        assertThat(battery.startCharging()).isFalse();
        assertThat(sim.groundTruth().recharges()).isEqualTo(1);
    }

    @Test
    void leavingTheStationEndsCharging() {
        Simulation sim = new Simulation(line(new WorldSpec.Battery(50, 1.0, 100, 10), List.of(new WorldSpec.Checkpoint(3, 3))));
        sim.robot().battery().startCharging();
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 40); // 0.64 m: off the 0.35 m station
        assertThat(sim.robot().battery().isCharging()).isFalse();
        sim.robot().battery().stopCharging();
        assertThat(sim.robot().battery().isCharging()).isFalse();
    }

    @Test
    void checkpointsCountOnlyInListedOrder() {
        List<WorldSpec.Checkpoint> cps = List.of(new WorldSpec.Checkpoint(2.0, 0.0), new WorldSpec.Checkpoint(1.0, 0.0));
        Simulation sim = new Simulation(line(WorldSpec.Battery.DEFAULT, cps));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 63); // ~1 m: over the second checkpoint, which does not count yet
        assertThat(sim.groundTruth().checkpointsReached()).isZero();
        Worlds.run(sim, 63); // ~2 m
        assertThat(sim.groundTruth().checkpointsReached()).isEqualTo(1);
        sim.robot().setWheelSpeeds(-0.5, -0.5);
        Worlds.run(sim, 63);
        assertThat(sim.groundTruth().checkpointsReached()).isEqualTo(2);
        assertThat(sim.groundTruth().checkpointsTotal()).isEqualTo(2);
        assertThat(sim.groundTruth().allCheckpointsReached()).isTrue();
    }
}
