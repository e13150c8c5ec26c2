package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The world file's {@code robot.sensorAnglesDeg}: a ray set of the robot's own, validated. */
class SensorAnglesTest {

    private static final String WORLD = """
            { "name": "rays", "arena": { "radiusM": 3 },
              "robot": { "x": 0, "y": 0, "headingDeg": 90 %s },
              "obstacles": [ { "shape": "circle", "x": 0.5, "y": 0.0, "radiusM": 0.1 } ],
              "checkpoints": [ { "x": 0, "y": 2 } ], "rechargeStation": { "x": -2, "y": 0, "radiusM": 0.3 } }
            """;

    private static String world(String rays) {
        return WORLD.formatted(rays.isEmpty() ? "" : ", \"sensorAnglesDeg\": " + rays);
    }

    private static List<String> problems(String json) {
        return catchThrowableOfType(WorldValidationException.class, () -> WorldFiles.parse(json)).problems();
    }

    @Test
    void withoutTheKeyTheRobotHasTheDefaultTwelveRays() {
        WorldSpec w = WorldFiles.parse(world(""));
        assertThat(w.robot().sensorAnglesDeg())
                .containsExactly(-90.0, -70.0, -50.0, -35.0, -20.0, -8.0, 8.0, 20.0, 35.0, 50.0, 70.0, 90.0);
        assertThat(new Simulation(w).robot().distanceSensors()).hasSize(12);
    }

    @Test
    void aRaySetOfItsOwnIsWhatTheSimulatedRobotCarriesAndSees() {
        WorldSpec w = WorldFiles.parse(world("[-90, -60, -30, 0, 30, 60, 90]"));
        Simulation sim = new Simulation(w);
        List<DistanceSensor> sensors = sim.robot().distanceSensors();
        assertThat(sensors).extracting(s -> Math.round(Math.toDegrees(s.getAngleRad()))).containsExactly(-90L, -60L, -30L, 0L, 30L, 60L, 90L);
        sim.step();
        // heading 90°: the pillar at (0.5, 0) lies to the right, where the -90° ray points: 0.5 - 0.1 - 0.12 from the rim
        assertThat(sensors.get(0).getValue()).isCloseTo(0.28, org.assertj.core.data.Offset.offset(0.01));
        assertThat(sensors.get(3).getValue()).isEqualTo(w.robot().sensorRangeM());
    }

    @Test
    void aBadRaySetIsRefusedWithItsKeyNamed() {
        assertThat(problems(world("[]"))).containsExactly("robot.sensorAnglesDeg: must hold 1 to 360 angles, got 0");
        assertThat(problems(world("45"))).containsExactly("robot.sensorAnglesDeg: expected an array of numbers, got a number (45)");
        assertThat(problems(world("[0, \"x\"]"))).containsExactly("robot.sensorAnglesDeg[1]: expected a number, got a string (\"x\")");
        assertThat(problems(world("[0, 200]"))).containsExactly("robot.sensorAnglesDeg[1]: must be from -180 to 180 degrees, got 200");
        assertThat(problems(world("[10, 10]"))).containsExactly(
                "robot.sensorAnglesDeg[1]: the angles must increase (rightmost sensor first, counter-clockwise), got 10 after 10");
    }
}
