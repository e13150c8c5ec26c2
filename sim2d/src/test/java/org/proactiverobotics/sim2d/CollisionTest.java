package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;

import org.junit.jupiter.api.Test;

class CollisionTest {

    private static WorldSpec boxAhead() {
        return Worlds.empty(5.0, 0.0, 0.0, 0.0)
                .withObstacles(List.of(WorldSpec.Obstacle.box(1.0, 0.0, 0.2, 2.0, 0.0)));
    }

    @Test
    void drivingIntoAnObstacleIsOneCollisionAndTheRobotStops() {
        Simulation sim = new Simulation(boxAhead());
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 100); // would be 1.6 m without the box
        GroundTruth t = sim.groundTruth();
        assertThat(t.collisions()).isEqualTo(1);
        // The face is at x = 0.9; the rim stops there (within dyn4j's penetration slop).
        assertThat(t.x()).isCloseTo(0.9 - 0.12, within(0.01));
        assertThat(t.minClearanceM()).isEqualTo(0.0);
        assertThat(sim.robot().distanceSensors().get(4).getValue()).isLessThan(0.01);
    }

    @Test
    void everyNewContactIsCounted() {
        Simulation sim = new Simulation(boxAhead());
        for (int bump = 1; bump <= 3; bump++) {
            sim.robot().setWheelSpeeds(0.5, 0.5);
            Worlds.run(sim, 60);
            sim.robot().setWheelSpeeds(-0.5, -0.5);
            Worlds.run(sim, 30);
            assertThat(sim.groundTruth().collisions()).isEqualTo(bump);
        }
    }

    @Test
    void theArenaWallCollidesToo() {
        Simulation sim = new Simulation(Worlds.empty(2.0, 0.0, 0.0, 33.0));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 200);
        GroundTruth t = sim.groundTruth();
        assertThat(t.collisions()).isEqualTo(1);
        assertThat(Math.hypot(t.x(), t.y())).isCloseTo(2.0 - 0.12, within(0.01));
    }

    @Test
    void slidingAlongTheWallIsOneCollision() {
        // Heading 60° off the wall's normal: the robot pushes into the wall and slides along its many segments.
        Simulation sim = new Simulation(Worlds.empty(2.0, 1.5, 0.0, 60.0));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 150);
        assertThat(sim.groundTruth().collisions()).isEqualTo(1);
    }

    @Test
    void pushingAndTurningAgainstAnObstacleIsOneCollision() {
        Simulation sim = new Simulation(boxAhead());
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 100);
        for (int i = 0; i < 20; i++) {
            sim.robot().setWheelSpeeds(-0.3, 0.3);
            Worlds.run(sim, 5);
            sim.robot().setWheelSpeeds(0.5, 0.3);
            Worlds.run(sim, 5);
        }
        assertThat(sim.groundTruth().collisions()).isEqualTo(1);
    }

    @Test
    void clearanceIsTrackedWithoutContact() {
        Simulation sim = new Simulation(boxAhead());
        assertThat(sim.groundTruth().minClearanceM()).isCloseTo(0.9 - 0.12, within(1e-9));
        sim.robot().setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 25); // 0.4 m
        assertThat(sim.groundTruth().minClearanceM()).isCloseTo(0.9 - 0.12 - 0.4, within(1e-9));
        assertThat(sim.groundTruth().collisions()).isZero();
    }
}
