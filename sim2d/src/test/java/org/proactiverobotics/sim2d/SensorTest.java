package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;

import org.junit.jupiter.api.Test;

class SensorTest {

    /** The default sensor that looks 8° left of the heading; heading -8° makes it look along +x. */
    private static final int FRONT = WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.indexOf(8.0);
    /** The default sensor that looks 90° left. */
    private static final int LEFT = WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.indexOf(90.0);
    private static final double ALONG_X = -8.0;

    private static WorldSpec wallAhead(double faceX) {
        // A 0.2 m thick, 3 m long box whose left face is at x = faceX.
        return Worlds.empty(5.0, 0.0, 0.0, ALONG_X)
                .withObstacles(List.of(WorldSpec.Obstacle.box(faceX + 0.1, 0.0, 0.2, 3.0, 0.0)));
    }

    @Test
    void defaultSensorsCoverFrontAndSides() {
        Simulation sim = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 0.0));
        List<DistanceSensor> ds = sim.robot().distanceSensors();
        assertThat(ds).hasSize(12);
        assertThat(ds.get(0).getAngleRad()).isEqualTo(-Math.PI / 2);
        assertThat(ds.get(LEFT).getAngleRad()).isEqualTo(Math.PI / 2);
        for (int i = 0; i < ds.size(); i++) {
            assertThat(ds.get(i).getIndex()).isEqualTo(i);
            assertThat(ds.get(i).getRangeM()).isEqualTo(1.0);
        }
    }

    @Test
    void obstacleAtAKnownDistanceReadsThatDistance() {
        Simulation sim = new Simulation(wallAhead(0.8));
        // From the rim: 0.8 m to the face minus the 0.12 m radius.
        assertThat(sim.robot().distanceSensors().get(FRONT).getValue()).isCloseTo(0.68, within(1e-9));
    }

    @Test
    void arenaWallAtAKnownDistanceReadsThatDistance() {
        Simulation sim = new Simulation(Worlds.empty(5.0, 4.0, 0.0, ALONG_X));
        assertThat(sim.robot().distanceSensors().get(FRONT).getValue()).isCloseTo(0.88, within(1e-6));
        // The wall is a ring of boxes; anywhere along it the polygon stays within 2 mm of the circle.
        Simulation diagonal = new Simulation(Worlds.empty(5.0, 2.8, 2.8, 45.0 + ALONG_X));
        double expected = 5.0 - Math.hypot(2.8, 2.8) - 0.12;
        assertThat(diagonal.robot().distanceSensors().get(FRONT).getValue()).isCloseTo(expected, within(0.002));
    }

    @Test
    void raysStopAtRange() {
        Simulation open = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 0.0));
        for (DistanceSensor s : open.robot().distanceSensors()) {
            assertThat(s.getValue()).isEqualTo(1.0);
        }
        // Just beyond range from the rim: 0.12 + 1.0 + 0.05.
        Simulation far = new Simulation(wallAhead(1.17));
        assertThat(far.robot().distanceSensors().get(FRONT).getValue()).isEqualTo(1.0);
        Simulation near = new Simulation(wallAhead(1.07));
        assertThat(near.robot().distanceSensors().get(FRONT).getValue()).isCloseTo(0.95, within(1e-9));
    }

    @Test
    void sideSensorsSeeSideObstacles() {
        // Robot facing +y; a circle 0.5 m to its left (-x) reads on the +90° sensor.
        Simulation sim = new Simulation(Worlds.empty(5.0, 0.0, 0.0, 90.0)
                .withObstacles(List.of(WorldSpec.Obstacle.circle(-0.8, 0.0, 0.2))));
        assertThat(sim.robot().distanceSensors().get(LEFT).getValue()).isCloseTo(0.48, within(1e-9));
        assertThat(sim.robot().distanceSensors().get(0).getValue()).isEqualTo(1.0);
    }

    @Test
    void readingsFollowTheRobotAfterEachStep() {
        Simulation sim = new Simulation(wallAhead(0.8));
        sim.robot().setWheelSpeeds(0.25, 0.25);
        double before = sim.robot().distanceSensors().get(FRONT).getValue();
        sim.step();
        double after = sim.robot().distanceSensors().get(FRONT).getValue();
        // Moving 8 mm along a heading of -8° brings the rim 8·cos 8° mm closer to the face.
        assertThat(before - after).isCloseTo(0.008 * Math.cos(Math.toRadians(8)), within(1e-9));
    }

    @Test
    void noisyReadingsScatterAroundTheTruthAndStayInRange() {
        SensorNoise noise = new SensorNoise(0.01, 0.01, 0.01);
        Simulation sim = new Simulation(wallAhead(0.8), noise);
        double sum = 0;
        double sumGps = 0;
        int n = 400;
        boolean differs = false;
        for (int i = 0; i < n; i++) {
            sim.step();
            double d = sim.robot().distanceSensors().get(FRONT).getValue();
            assertThat(d).isBetween(0.68 - 0.06, 0.68 + 0.06);
            differs |= d != 0.68;
            assertThat(sim.robot().distanceSensors().get(0).getValue()).isBetween(0.9, 1.0);
            sum += d;
            sumGps += sim.robot().gps().getValues()[0];
        }
        assertThat(differs).isTrue();
        assertThat(sum / n).isCloseTo(0.68, within(0.003));
        assertThat(sumGps / n).isCloseTo(0.0, within(0.003));
    }

    @Test
    void readingTwiceInOneStepGivesTheSameNoisyValue() {
        Simulation sim = new Simulation(wallAhead(0.8), SensorNoise.SMALL);
        sim.step();
        assertThat(sim.robot().gps().getValues()).containsExactly(sim.robot().gps().getValues());
        assertThat(sim.robot().distanceSensors().get(3).getValue())
                .isEqualTo(sim.robot().distanceSensors().get(3).getValue());
    }
}
