package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

class DeterminismTest {

    /** A crude wanderer: drives ahead, turns away from whatever the front sensors see. */
    static void wander(SimRobot robot) {
        double left = Math.min(robot.distanceSensors().get(3).getValue(), robot.distanceSensors().get(2).getValue());
        double right = Math.min(robot.distanceSensors().get(4).getValue(), robot.distanceSensors().get(5).getValue());
        if (Math.min(left, right) < 0.35) {
            double turn = left < right ? 0.3 : -0.3;
            robot.setWheelSpeeds(-turn, turn);
        } else {
            robot.setWheelSpeeds(0.5, 0.45);
        }
    }

    /** Bits of every state variable over a run. */
    private static List<Long> trace(Simulation sim, int steps) {
        List<Long> bits = new ArrayList<>();
        for (int i = 0; i < steps; i++) {
            wander(sim.robot());
            sim.step();
            GroundTruth t = sim.groundTruth();
            bits.add(Double.doubleToRawLongBits(t.x()));
            bits.add(Double.doubleToRawLongBits(t.y()));
            bits.add(Double.doubleToRawLongBits(t.headingRad()));
            bits.add(Double.doubleToRawLongBits(sim.robot().distanceSensors().get(4).getValue()));
            bits.add(Double.doubleToRawLongBits(sim.robot().gps().getValues()[0]));
            bits.add((long) t.collisions());
        }
        return bits;
    }

    @Test
    void sameWorldAndSeedGiveTheSameTrajectoryBitForBit() {
        WorldSpec world = WorldFiles.bundled("cluttered-arena");
        List<Long> a = trace(new Simulation(world, SensorNoise.SMALL), 3000);
        List<Long> b = trace(new Simulation(world, SensorNoise.SMALL), 3000);
        assertThat(a).isEqualTo(b);
    }

    @Test
    void interleavedSimulationsDoNotDisturbEachOther() {
        WorldSpec world = WorldFiles.bundled("reference-arena");
        List<Long> alone = trace(new Simulation(world, SensorNoise.SMALL), 1000);
        Simulation s1 = new Simulation(world, SensorNoise.SMALL);
        Simulation s2 = new Simulation(world, SensorNoise.SMALL);
        List<Long> t1 = new ArrayList<>();
        for (int i = 0; i < 1000; i++) {
            t1.addAll(trace(s1, 1));
            trace(s2, 1);
        }
        assertThat(t1).isEqualTo(alone);
    }

    @Test
    void anotherSeedGivesOtherNoise() {
        WorldSpec world = WorldFiles.bundled("reference-arena");
        WorldSpec reseeded = new WorldSpec(world.name(), world.timeStepMs(), world.maxSimTimeS(), world.seed() + 1,
                world.arena(), world.robot(), world.obstacles(), world.checkpoints(), world.checkpointRadiusM(),
                world.rechargeStation(), world.battery());
        Simulation a = new Simulation(world, SensorNoise.SMALL);
        Simulation b = new Simulation(reseeded, SensorNoise.SMALL);
        a.step();
        b.step();
        assertThat(a.robot().gps().getValues()[0]).isNotEqualTo(b.robot().gps().getValues()[0]);
    }
}
