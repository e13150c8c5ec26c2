package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** Several robots in one world: their bodies collide, their rays see each other, their noise is their own. */
class FleetSimulationTest {

    private static final WorldSpec.Battery BATTERY = WorldSpec.Battery.DEFAULT;

    private static WorldSpec.RobotEntry robot(int id, double x, double y, double headingDeg) {
        return new WorldSpec.RobotEntry(id, new WorldSpec.Robot(x, y, headingDeg, 0.12, 0.5, 1.0),
                List.of(new WorldSpec.Checkpoint(x, y + 1.0)));
    }

    private static WorldSpec fleet(long seed, WorldSpec.RobotEntry... robots) {
        return WorldSpec.fleet("fleet", 32, 600, seed, new WorldSpec.Arena(5.0), List.of(robots), List.of(), 0.25,
                List.of(new WorldSpec.RechargeStation(0.0, -3.0, 0.35), new WorldSpec.RechargeStation(0.0, 3.0, 0.35)),
                BATTERY);
    }

    @Test
    void twoRobotsDrivenIntoEachOtherCollideOnceEach() {
        Simulation sim = new Simulation(fleet(7, robot(1, -1.0, 0.0, 0.0), robot(2, 1.0, 0.0, 180.0)));
        assertThat(sim.robotCount()).isEqualTo(2);
        sim.robot(0).setWheelSpeeds(0.3, 0.3);
        sim.robot(1).setWheelSpeeds(0.3, 0.3);
        Worlds.run(sim, 150); // 1.44 m each without the other: they meet near x = 0
        for (int i = 0; i < 2; i++) {
            GroundTruth t = sim.groundTruth(i);
            assertThat(t.collisions()).as("robot %d collisions", i).isEqualTo(1);
            assertThat(t.robotCollisions()).as("robot %d robot collisions", i).isEqualTo(1);
        }
        // Neither passed through the other: their rims touch (within dyn4j's slop).
        assertThat(sim.groundTruth(1).x() - sim.groundTruth(0).x()).isCloseTo(0.24, within(0.02));
    }

    @Test
    void aWallCollisionIsNotARobotCollision() {
        Simulation sim = new Simulation(fleet(7, robot(1, 4.0, 0.0, 0.0), robot(2, -4.0, 0.0, 180.0)));
        sim.robot(0).setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 100);
        assertThat(sim.groundTruth(0).collisions()).isEqualTo(1);
        assertThat(sim.groundTruth(0).robotCollisions()).isZero();
        assertThat(sim.groundTruth(1).collisions()).isZero();
    }

    @Test
    void aRobotsRaysReadTheOtherRobotsBody() {
        // Robot 2 sits 0.8 m ahead of robot 1 (centre to centre): robot 1's front rays read 0.8 - 0.12 - 0.12.
        Simulation sim = new Simulation(fleet(7, robot(1, 0.0, 0.0, 0.0), robot(2, 0.8, 0.0, 90.0)));
        List<DistanceSensor> rays = sim.robot(0).distanceSensors();
        DistanceSensor ahead = rays.stream().filter(s -> Math.abs(s.getAngleRad()) < Math.toRadians(10)).findFirst().orElseThrow();
        // An 8° ray meets the disc a little before the centre line: the disc's near side along the ray.
        double a = ahead.getAngleRad();
        double along = 0.8 * Math.cos(a) - Math.sqrt(0.12 * 0.12 - Math.pow(0.8 * Math.sin(a), 2));
        assertThat(ahead.getValue()).isCloseTo(along - 0.12, within(1e-6));
        // Its own body never shadows its rays: robot 2's rays looking sideways read their full range.
        for (DistanceSensor s : sim.robot(1).distanceSensors()) {
            assertThat(s.getValue()).isGreaterThan(0.0);
        }
        // And robot 2 sees robot 1 off its left flank (+90° from its heading of 90° is along -x).
        List<DistanceSensor> itsRays = sim.robot(1).distanceSensors();
        DistanceSensor left = itsRays.get(itsRays.size() - 1);
        assertThat(left.getAngleRad()).isCloseTo(Math.PI / 2, within(1e-12));
        assertThat(left.getValue()).isCloseTo(0.8 - 0.24, within(1e-6));
    }

    @Test
    void aRobotThatStoppedStaysABodyOthersSeeAndHit() {
        Simulation sim = new Simulation(fleet(7, robot(1, -1.0, 0.0, 0.0), robot(2, 1.0, 0.0, 180.0)));
        // Robot 2 has reached its mission's end and stands still; robot 1 drives on into it.
        sim.robot(0).setWheelSpeeds(0.4, 0.4);
        Worlds.run(sim, 100); // 1.28 m: the gap between their rims is 0.48 m, in the -8° ray's path
        DistanceSensor ahead = sim.robot(0).distanceSensors().get(5);
        assertThat(ahead.getValue()).isLessThan(1.0);
        Worlds.run(sim, 150);
        assertThat(sim.groundTruth(0).robotCollisions()).isEqualTo(1);
        assertThat(sim.groundTruth(1).robotCollisions()).isEqualTo(1);
        // A body to the end: robot 1 never drove through it (the push moves both; their rims stay in contact).
        assertThat(sim.groundTruth(1).x() - sim.groundTruth(0).x()).isCloseTo(0.24, within(0.02));
    }

    @Test
    void eachRobotChargesAtAnyStation() {
        Simulation sim = new Simulation(fleet(7, robot(1, 0.0, -3.0, 0.0), robot(2, 0.0, 3.0, 0.0))
                .withBattery(new WorldSpec.Battery(50.0, 1.0, 100.0, 10.0)));
        assertThat(sim.robot(0).battery().isAtStation()).isTrue();
        assertThat(sim.robot(1).battery().isAtStation()).isTrue();
        assertThat(sim.robot(1).battery().startCharging()).isTrue();
        Worlds.run(sim, 10);
        assertThat(sim.robot(1).battery().getLevelPct()).isGreaterThan(50.0);
        assertThat(sim.robot(0).battery().getLevelPct()).isEqualTo(50.0);
    }

    @Test
    void eachRobotHasItsOwnCheckpoints() {
        Simulation sim = new Simulation(fleet(7, robot(1, -2.0, 0.0, 90.0), robot(2, 2.0, 0.0, 90.0)));
        sim.robot(0).setWheelSpeeds(0.5, 0.5);
        Worlds.run(sim, 70); // 1.12 m: robot 1 passes (-2, 1); robot 2 stands
        assertThat(sim.groundTruth(0).allCheckpointsReached()).isTrue();
        assertThat(sim.groundTruth(1).checkpointsReached()).isZero();
    }

    @Test
    void robotsDrawTheirOwnNoiseAndRobotZeroDrawsTheOneRobotStream() {
        WorldSpec.RobotEntry first = robot(1, -2.0, 0.0, 0.0);
        Simulation alone = new Simulation(fleet(11, first), SensorNoise.SMALL);
        Simulation two = new Simulation(fleet(11, first, robot(2, 2.0, 0.0, 0.0)), SensorNoise.SMALL);
        double[] a = alone.robot(0).gps().getValues();
        double[] b0 = two.robot(0).gps().getValues();
        double[] b1 = two.robot(1).gps().getValues();
        assertThat(b0).containsExactly(a);
        // Robot 2's error from its true position differs from robot 1's: not the same stream.
        assertThat(b1[0] - 2.0).isNotEqualTo(b0[0] + 2.0);
    }

    /** Bits of every robot's state over a run of three wanderers that meet. */
    private static List<Long> trace(WorldSpec world, int steps) {
        Simulation sim = new Simulation(world, SensorNoise.SMALL);
        List<Long> bits = new ArrayList<>();
        for (int s = 0; s < steps; s++) {
            for (int i = 0; i < sim.robotCount(); i++) {
                DeterminismTest.wander(sim.robot(i));
            }
            sim.step();
            for (int i = 0; i < sim.robotCount(); i++) {
                GroundTruth t = sim.groundTruth(i);
                bits.add(Double.doubleToRawLongBits(t.x()));
                bits.add(Double.doubleToRawLongBits(t.y()));
                bits.add(Double.doubleToRawLongBits(t.headingRad()));
                bits.add(Double.doubleToRawLongBits(sim.robot(i).distanceSensors().get(6).getValue()));
                bits.add(Double.doubleToRawLongBits(sim.robot(i).gps().getValues()[0]));
                bits.add((long) t.collisions() << 32 | t.robotCollisions());
            }
        }
        return bits;
    }

    @Test
    void aThreeRobotWorldIsDeterministicBitForBit() {
        WorldSpec world = fleet(3, robot(1, -1.0, 0.0, 0.0), robot(2, 1.0, 0.1, 180.0), robot(3, 0.0, 1.0, -90.0));
        List<Long> a = trace(world, 2000);
        List<Long> b = trace(world, 2000);
        assertThat(a).isEqualTo(b);
        // They did meet: the run is worth comparing.
        Simulation sim = new Simulation(world, SensorNoise.SMALL);
        assertThat(sim.robotCount()).isEqualTo(3);
    }

    @Test
    void continuousDetectionFollowsTheFastestRobot() {
        WorldSpec.RobotEntry slow = robot(1, -1.0, 0.0, 0.0);
        WorldSpec.RobotEntry fast = new WorldSpec.RobotEntry(2, new WorldSpec.Robot(1.0, 0.0, 0.0, 0.05, 5.0, 1.0),
                List.of(new WorldSpec.Checkpoint(0.0, 0.0)));
        assertThat(new Simulation(fleet(1, slow)).world().getSettings().getContinuousDetectionMode())
                .isEqualTo(org.dyn4j.dynamics.ContinuousDetectionMode.NONE);
        assertThat(new Simulation(fleet(1, slow, fast)).world().getSettings().getContinuousDetectionMode())
                .isEqualTo(org.dyn4j.dynamics.ContinuousDetectionMode.ALL);
    }
}
