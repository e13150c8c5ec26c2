package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The wheel encoders: the applied wheel speeds over each step, in metres, noise or not. */
class WheelOdometerTest {

    @Test
    void eachWheelTravelsItsSpeedTimesTheTimeBackwardsNegative() {
        Simulation sim = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 0.0));
        assertThat(sim.robot().odometer().getTravelM()).containsExactly(0.0, 0.0);
        sim.robot().setWheelSpeeds(0.4, 0.4);
        Worlds.run(sim, 50); // 1.6 s
        assertThat(sim.robot().odometer().getTravelM()[0]).isCloseTo(0.64, within(1e-9));
        assertThat(sim.robot().odometer().getTravelM()[1]).isCloseTo(0.64, within(1e-9));
        assertThat(sim.groundTruth().distanceM()).isCloseTo(0.64, within(1e-9));
        sim.robot().setWheelSpeeds(-0.1, 0.3);
        Worlds.run(sim, 25); // 0.8 s more
        assertThat(sim.robot().odometer().getTravelM()[0]).isCloseTo(0.64 - 0.08, within(1e-9));
        assertThat(sim.robot().odometer().getTravelM()[1]).isCloseTo(0.64 + 0.24, within(1e-9));
    }

    @Test
    void aWheelPushingAgainstAnObstacleStillRolls() {
        Simulation sim = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 0.0)
                .withObstacles(List.of(WorldSpec.Obstacle.box(1.0, 0.0, 0.2, 2.0, 0.0))));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 100); // 1.6 m of wheel travel; the body stops at the box, 0.78 m on
        assertThat(sim.robot().odometer().getTravelM()[0]).isCloseTo(1.6, within(1e-9));
        assertThat(sim.groundTruth().distanceM()).isLessThan(0.8);
    }

    @Test
    void anEmptyBatteryTurnsNoWheel() {
        WorldSpec base = Worlds.empty(5.0, 0.0, 0.0, 0.0);
        Simulation sim = new Simulation(base.withBattery(new WorldSpec.Battery(1, 10.0, 100, 10))); // 1 % lasts 0.1 m
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 50);
        assertThat(sim.robot().battery().getLevelPct()).isZero();
        double[] flat = sim.robot().odometer().getTravelM();
        Worlds.run(sim, 50);
        assertThat(sim.robot().odometer().getTravelM()).containsExactly(flat);
        assertThat(flat[0]).isCloseTo(sim.groundTruth().distanceM(), within(0.02));
    }

    @Test
    void noiseLeavesTheOdometerExact() {
        Simulation exact = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 0.0));
        Simulation noisy = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 0.0), SensorNoise.SMALL);
        for (Simulation sim : List.of(exact, noisy)) {
            sim.robot().setWheelSpeeds(0.3, -0.2);
            Worlds.run(sim, 40);
        }
        assertThat(noisy.robot().odometer().getTravelM()).containsExactly(exact.robot().odometer().getTravelM());
    }
}
