package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class DriveTest {

    @Test
    void equalWheelSpeedsDriveAStraightLine() {
        Simulation sim = new Simulation(Worlds.empty(5.0, -2.0, 0.0, 0.0));
        sim.robot().setWheelSpeeds(0.4, 0.4);
        Worlds.run(sim, 100); // 3.2 s at 0.4 m/s = 1.28 m
        GroundTruth t = sim.groundTruth();
        assertThat(t.x()).isCloseTo(-2.0 + 1.28, within(1e-9));
        assertThat(t.y()).isCloseTo(0.0, within(1e-9));
        assertThat(t.headingRad()).isCloseTo(0.0, within(1e-9));
        assertThat(t.distanceM()).isCloseTo(1.28, within(1e-9));
        assertThat(sim.simTimeMs()).isEqualTo(3200);
    }

    @Test
    void oppositeWheelSpeedsTurnInPlace() {
        Simulation sim = new Simulation(Worlds.empty(5.0, 1.0, 1.0, 0.0));
        sim.robot().setWheelSpeeds(-0.1, 0.1); // ω = 0.2 / 0.24 rad/s, counter-clockwise
        Worlds.run(sim, 50); // 1.6 s
        double expected = 0.2 / sim.robot().axleWidthM() * 1.6;
        GroundTruth t = sim.groundTruth();
        assertThat(t.headingRad()).isCloseTo(expected, within(1e-9));
        assertThat(sim.robot().inertialUnit().getRollPitchYaw()[2]).isCloseTo(expected, within(1e-9));
        assertThat(t.x()).isCloseTo(1.0, within(1e-9));
        assertThat(t.y()).isCloseTo(1.0, within(1e-9));
    }

    @Test
    void wheelSpeedsAreClampedToMaxSpeed() {
        Simulation sim = new Simulation(Worlds.empty(5.0, -3.0, 0.0, 0.0));
        sim.robot().setWheelSpeeds(7.0, 9.0);
        assertThat(sim.robot().leftSpeedMps()).isEqualTo(0.5);
        assertThat(sim.robot().rightSpeedMps()).isEqualTo(0.5);
        Worlds.run(sim, 125); // 4 s at 0.5 m/s
        assertThat(sim.groundTruth().x()).isCloseTo(-1.0, within(1e-9));
        sim.robot().setWheelSpeeds(-3.0, Double.NaN);
        assertThat(sim.robot().leftSpeedMps()).isEqualTo(-0.5);
        assertThat(sim.robot().rightSpeedMps()).isEqualTo(0.0);
    }

    @Test
    void headingFollowsTheYawConvention() {
        Simulation sim = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 90.0));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 31);
        assertThat(sim.robot().gps().getValues()[1]).isCloseTo(0.5 * 0.992, within(1e-9));
        assertThat(sim.robot().inertialUnit().getRollPitchYaw()).containsExactly(0.0, 0.0, Math.PI / 2);
    }
}
