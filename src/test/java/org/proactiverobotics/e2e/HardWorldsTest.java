package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Issue 17's failures, each in a hand-made world over the direct link: the battery promise when
 * the robot is stuck on a wall with a doorway, a tour needing several recharges, a fast robot in
 * clutter, a large robot among pillars.
 */
class HardWorldsTest {

    /**
     * A wall across the arena with one 0.6 m doorway between the start and the checkpoint, and a
     * battery that runs low while the robot follows the wall. Without a map the robot may never
     * find the doorway; whatever it does, it must go and charge in time: never a flat battery.
     * The station is on the robot's side of the wall.
     */
    static final String DOORWAY = """
            { "name": "doorway-battery", "maxSimTimeS": 240, "seed": 3,
              "arena": { "radiusM": 4.0 },
              "robot": { "x": -1.5, "y": -2.0, "headingDeg": 90.0 },
              "obstacles": [
                { "shape": "box", "x": -1.6, "y": 0.0, "widthM": 5.2, "heightM": 0.2 },
                { "shape": "box", "x": 2.9, "y": 0.0, "widthM": 2.6, "heightM": 0.2 } ],
              "checkpoints": [ { "x": -1.0, "y": 2.5 } ],
              "rechargeStation": { "x": -2.5, "y": -2.0, "radiusM": 0.35 },
              "battery": { "initial": 60.0, "drainPerMeter": 2.5 } }
            """;

    /**
     * Out and back across an empty arena with a tight battery: 8 m legs at 9 %/m (72 % of a full
     * charge), so the cautious "checkpoint and back" rule asks for more than a full charge; the
     * tour needs a recharge before each long leg.
     */
    static final String TOUR = """
            { "name": "tight-tour", "maxSimTimeS": 400, "seed": 4,
              "arena": { "radiusM": 5.0 },
              "robot": { "x": 0.0, "y": -0.5, "headingDeg": 0.0 },
              "checkpoints": [ { "x": 4.0, "y": 0.0 }, { "x": -4.0, "y": 0.0 }, { "x": 4.0, "y": 0.3 }, { "x": -4.0, "y": 0.3 } ],
              "rechargeStation": { "x": 0.0, "y": 0.0, "radiusM": 0.35 },
              "battery": { "initial": 100.0, "drainPerMeter": 9.0, "rechargeRatePerS": 20.0 } }
            """;

    /**
     * The last checkpoint 3.2 m from the first in a straight line but behind a wall whose only gap
     * is 3.5 m to the right, in space the robot has not seen; the station 3.2 m from the first
     * checkpoint. 6 %/m: the way round (about 8 m) and the way back do not fit one charge, the way
     * from the station to the last checkpoint does.
     */
    static final String LAST_BEHIND_WALL = """
            { "name": "last-behind-wall", "maxSimTimeS": 400, "seed": 5,
              "arena": { "radiusM": 4.0 },
              "robot": { "x": 0.0, "y": -1.0, "headingDeg": 90.0 },
              "obstacles": [ { "shape": "box", "x": -0.85, "y": 0.0, "widthM": 7.3, "heightM": 0.2 } ],
              "checkpoints": [ { "x": 0.5, "y": -1.5 }, { "x": -1.5, "y": 1.0 } ],
              "rechargeStation": { "x": -2.5, "y": -2.5, "radiusM": 0.35 },
              "battery": { "initial": 100.0, "drainPerMeter": 6.0, "rechargeRatePerS": 20.0 } }
            """;

    /** The fewest recharges TOUR can be done with: one before each of the three legs after the first. */
    static final int TOUR_MIN_RECHARGES = 3;

    /**
     * A 0.3 m robot through a field of pillars with passages of 0.9 m (1.5 of its diameters). Eight
     * rays leave its flanks blind to a 0.15 m pillar (45° between rays is 0.24 m at its rim), so it
     * carries a ray every 15° across the front half, as a laser scanner would give.
     */
    static final String PILLARS;

    static {
        StringBuilder pillars = new StringBuilder();
        for (int row = 0; row < 3; row++) {
            for (int col = -2; col <= 2; col++) {
                double x = col * 1.05 + (row % 2 == 0 ? 0.0 : 0.525);
                double y = -1.05 + row * 1.05;
                pillars.append(pillars.length() == 0 ? "" : ",")
                        .append("{ \"shape\": \"circle\", \"x\": ").append(x).append(", \"y\": ").append(y)
                        .append(", \"radiusM\": 0.075 }");
            }
        }
        PILLARS = """
                { "name": "big-robot-pillars", "maxSimTimeS": 200, "seed": 5,
                  "arena": { "radiusM": 4.0 },
                  "robot": { "x": 0.0, "y": -3.0, "headingDeg": 90.0, "radiusM": 0.3,
                             "sensorAnglesDeg": [-90, -75, -60, -45, -30, -20, -8, 8, 20, 30, 45, 60, 75, 90] },
                  "obstacles": [ %s ],
                  "checkpoints": [ { "x": 0.3, "y": 2.8 }, { "x": -1.5, "y": -2.6 } ],
                  "rechargeStation": { "x": 2.5, "y": -2.5, "radiusM": 0.45 } }
                """.formatted(pillars);
    }

    @Test
    void aRobotStuckOnAWallWithADoorwayStillChargesInTime() throws Exception {
        MissionReport report = run(DOORWAY);
        // before the battery promise and the map: BATTERY_DEPLETED at 69 s, never released from the wall.
        // Now the route through the doorway is found on the map; the battery is never flat.
        assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(report.minBattery()).isPositive();
        assertThat(report.collisions()).isZero();
    }

    /**
     * The same wall with a 0.5 m doorway, the station this time in the far corner of the robot's
     * side. Before, the robot never found the door and ran flat at 68 s; without the map it still
     * never found it but charged in time (TIME_LIMIT, battery never flat); with the map's route it
     * goes through.
     */
    @Test
    void aNarrowerDoorwayIsFoundOnTheMapAndTheBatteryIsNeverFlat() throws Exception {
        String world = DOORWAY.replace("\"x\": -1.6, \"y\": 0.0, \"widthM\": 5.2", "\"x\": -1.475, \"y\": 0.0, \"widthM\": 5.45")
                .replace("\"x\": 2.9, \"y\": 0.0, \"widthM\": 2.6", "\"x\": 2.975, \"y\": 0.0, \"widthM\": 2.45")
                .replace("\"x\": -2.5, \"y\": -2.0, \"radiusM\": 0.35", "\"x\": 2.0, \"y\": -2.5, \"radiusM\": 0.35")
                .replace("\"maxSimTimeS\": 240", "\"maxSimTimeS\": 400");
        MissionReport report = run(world);
        assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(report.minBattery()).isGreaterThan(2.0);
        assertThat(report.collisions()).isZero();
    }

    @Test
    void aTourNeedingSeveralRechargesIsAccomplishedWithoutLivelock() throws Exception {
        MissionReport report = run(TOUR);
        assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(report.recharges()).isBetween(TOUR_MIN_RECHARGES, TOUR_MIN_RECHARGES + 1);
        assertThat(report.minBattery()).isPositive();
    }

    /**
     * The last leg runs past the point of no return into space the robot has not seen. Finishing
     * is judged on the route to the checkpoint as planned (re-planned as walls appear), not the
     * straight line (which let a robot explore a wall's wrong end until the battery was flat), and
     * not only on seen cells (which turned the robot back at the same gap after every recharge:
     * 10 recharges and TIME_LIMIT).
     */
    @Test
    void aLastCheckpointBehindAWallIsReachedAfterOneRechargeNeverFlat() throws Exception {
        MissionReport report = run(LAST_BEHIND_WALL);
        assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(report.recharges()).isEqualTo(1);
        assertThat(report.minBattery()).isPositive();
        assertThat(report.collisions()).isZero();
    }

    /** Dense clutter at 1.0 m/s; seed 4 clipped an obstacle with the fixed avoidance distances. */
    @ParameterizedTest(name = "dense world {0} at 1.0 m/s")
    @ValueSource(longs = {1, 2, 3, 4})
    void aFastRobotInDenseClutterNeverCollides(long seed) throws Exception {
        MissionReport report = run(denseFastWorld(seed));
        assertThat(report.collisions()).isZero();
        assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
    }

    @Test
    void aLargeRobotAmongPillarsNeverCollides() throws Exception {
        MissionReport report = run(PILLARS);
        assertThat(report.collisions()).isZero();
        assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
    }

    private static MissionReport run(String json) throws Exception {
        WorldSpec world = WorldFiles.parse(json, "hard-world");
        Path out = Files.createTempDirectory("hard-world-" + world.name() + "-");
        MissionReport report = new Mission(new MissionOptions(world, null, null, null, "safety-first", 1)
                .withLink(MissionOptions.Link.DIRECT)).run(out);
        System.out.printf("%s: %s, checkpoints %d, collisions %d, battery min %.1f %%, recharges %d, %.1f s (%s)%n",
                world.name(), report.outcome(), report.checkpointsReached(), report.collisions(), report.minBattery(),
                report.recharges(), report.simTimeS(), out);
        return report;
    }
    /** A dense cluttered world for a fast robot: gaps of 0.5 m, up to 24 obstacles, 1.0 m/s. */
    static String denseFastWorld(long seed) {
        return RandomWorldsTest.clutteredWorld("dense-fast-" + seed, seed, 24, 0.5, 1.0);
    }

}
