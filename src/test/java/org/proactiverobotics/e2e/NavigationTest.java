package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Issue 17, rooms and mazes: the Mapping scenario's occupancy map and ReachDestination's route
 * on it take the robot through doors and mazes, and a checkpoint that no route reaches ends the
 * mission with CHECKPOINT_UNREACHABLE, in bounded time, the battery far from flat.
 */
class NavigationTest {

    /** Two rooms side by side; the door (0.6 m) is in the far corner of the wall between them, off the straight line. */
    static final String DOOR_ROOM = """
            { "name": "door-room", "maxSimTimeS": 120, "arena": {"radiusM": 4.5},
              "robot": {"x": -1.5, "y": -1.5, "headingDeg": 0},
              "obstacles": [
                {"shape": "box", "x": 0.0, "y": -1.0, "widthM": 0.1, "heightM": 4.0, "angleDeg": 0},
                {"shape": "box", "x": 0.0, "y": 2.3, "widthM": 0.1, "heightM": 1.4, "angleDeg": 0},
                {"shape": "box", "x": 0.0, "y": 3.0, "widthM": 6.2, "heightM": 0.1, "angleDeg": 0},
                {"shape": "box", "x": 0.0, "y": -3.0, "widthM": 6.2, "heightM": 0.1, "angleDeg": 0},
                {"shape": "box", "x": -3.05, "y": 0.0, "widthM": 0.1, "heightM": 6.1, "angleDeg": 0},
                {"shape": "box", "x": 3.05, "y": 0.0, "widthM": 0.1, "heightM": 6.1, "angleDeg": 0}
              ],
              "checkpoints": [{"x": 1.5, "y": -1.5}],
              "rechargeStation": {"x": -2.2, "y": -2.2, "radiusM": 0.35} }
            """;

    /** The second checkpoint is inside a closed box. */
    static final String WALLED_IN = """
            { "name": "walled-in", "maxSimTimeS": 300, "arena": {"radiusM": 4.0},
              "robot": {"x": 0.0, "y": -2.5, "headingDeg": 90},
              "obstacles": [
                {"shape": "box", "x": 0.0, "y": 0.0, "widthM": 1.6, "heightM": 0.1, "angleDeg": 0},
                {"shape": "box", "x": 0.0, "y": 1.5, "widthM": 1.6, "heightM": 0.1, "angleDeg": 0},
                {"shape": "box", "x": -0.75, "y": 0.75, "widthM": 0.1, "heightM": 1.6, "angleDeg": 0},
                {"shape": "box", "x": 0.75, "y": 0.75, "widthM": 0.1, "heightM": 1.6, "angleDeg": 0}
              ],
              "checkpoints": [{"x": -2.0, "y": -1.0}, {"x": 0.0, "y": 0.75}],
              "rechargeStation": {"x": 2.2, "y": -2.2, "radiusM": 0.35} }
            """;

    @Test
    void throughTheDoorIntoTheNextRoom() {
        Missions.Run run = Missions.direct(WorldFiles.parse(DOOR_ROOM, "door-room"), "safety-first");
        assertThat(run.report().outcome()).as("see %s", run.outDir()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(run.report().collisions()).isZero();
    }

    @Test
    void aWalledInCheckpointEndsTheMissionAsUnreachableTheSameOnH2AsOnTheDirectLink() throws Exception {
        WorldSpec world = WorldFiles.parse(WALLED_IN, "walled-in");
        Missions.Run direct = Missions.direct(world, "safety-first");
        assertThat(direct.report().outcome()).as("see %s", direct.outDir()).isEqualTo(Outcome.CHECKPOINT_UNREACHABLE);
        assertThat(direct.report().checkpointsReached()).isEqualTo(1);
        assertThat(direct.report().simTimeS()).as("bounded: well within the world's 300 s").isLessThan(90);
        assertThat(direct.report().minBattery()).isGreaterThan(50);
        assertThat(direct.report().success()).isFalse();
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Missions.Run h2 = Missions.run(world, db, "safety-first");
            assertThat(h2.deterministicPart()).isEqualTo(direct.deterministicPart());
            // the engine marked it in the shared table, and its map is there for another process to read
            try (Connection c = db.dataSource().getConnection();
                 PreparedStatement ps = c.prepareStatement("SELECT (SELECT COUNT(*) FROM checkpoints WHERE unreachable),"
                         + " (SELECT COUNT(*) FROM occupancy_map)");
                 ResultSet rs = ps.executeQuery()) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getInt(1)).isEqualTo(1);
                assertThat(rs.getInt(2)).isPositive();
            }
        }
    }

    @ParameterizedTest(name = "{0} number {2}, seed {1}")
    @CsvSource({"maze, 17, 3", "maze, 17, 8", "rooms, 17, 2", "pillars, 17, 8", "corridors, 17, 4", "battery, 17, 5"})
    void generatedWorldsAreAccomplishedWithoutCollision(String kind, long seed, int number) {
        WorldSpec world = new WorldGenerator(WorldGenerator.Kind.valueOf(kind.toUpperCase(java.util.Locale.ROOT)))
                .world(seed, number);
        Missions.Run run = Missions.direct(world, "safety-first");
        assertThat(run.report().outcome()).as("see %s", run.outDir()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(run.report().collisions()).isZero();
        assertThat(run.report().minBattery()).isPositive();
    }

    /**
     * With small sensor noise (1 cm GPS, 0.5° heading, 1 cm distance) the map, the route, the
     * collision monitor and the drain estimate still work: before, a free ray reading a little under
     * its range drew a ring of walls round the robot and every mission ended unreachable within 2 s,
     * and GPS noise summed step by step made the cost per metre far too low for the battery promise.
     */
    @ParameterizedTest(name = "{0} number {2}, seed {1}, small noise")
    @CsvSource({"rooms, 17, 2", "maze, 17, 3", "battery, 17, 5", "pillars, 17, 8"})
    void generatedWorldsAreAccomplishedWithSmallNoise(String kind, long seed, int number) {
        WorldSpec world = new WorldGenerator(WorldGenerator.Kind.valueOf(kind.toUpperCase(java.util.Locale.ROOT)))
                .world(seed, number);
        Missions.Run run = Missions.direct(world, "safety-first", org.proactiverobotics.app.mission.NoiseLevel.SMALL);
        assertThat(run.report().outcome()).as("see %s", run.outDir()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(run.report().collisions()).isZero();
        assertThat(run.report().minBattery()).isPositive();
        // a noisy fix at the station's edge does not break one stop into several charging sessions
        assertThat(run.report().recharges()).isLessThanOrEqualTo(Missions.direct(world, "safety-first").report().recharges());
    }

    /**
     * A door a noisy reading drew shut opens again: the map keeps evidence per cell, and the rays
     * that pass through the door later take a wall seen once away (before, this world ended
     * CHECKPOINT_UNREACHABLE at 36 s under small noise).
     */
    @Test
    void aDoorwayANoisyReadingClosedOpensAgain() {
        WorldSpec world = new WorldGenerator(WorldGenerator.Kind.CORRIDORS).world(17, 3);
        Missions.Run run = Missions.direct(world, "safety-first", org.proactiverobotics.app.mission.NoiseLevel.SMALL);
        assertThat(run.report().outcome()).as("see %s", run.outDir()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(run.report().collisions()).isZero();
    }

    /**
     * Corridor worlds under small noise: a gap between a wall's end and the curved rim that the
     * noisy map drew a little narrower is taken with half a cell less room (before: 004 ended
     * CHECKPOINT_UNREACHABLE at 34 s), and the battery holds on the last leg, judged on the
     * planned route and the way back over seen cells (13, like 20, ran flat exploring a wall's wrong
     * end, taken for near by the straight line).
     */
    @ParameterizedTest(name = "corridors number {0}, small noise")
    @CsvSource({"4", "13"})
    void corridorGapsANoisyMapNarrowedAreDrivenAndTheBatteryHolds(int number) {
        WorldSpec world = new WorldGenerator(WorldGenerator.Kind.CORRIDORS).world(17, number);
        Missions.Run run = Missions.direct(world, "safety-first", org.proactiverobotics.app.mission.NoiseLevel.SMALL);
        assertThat(run.report().outcome()).as("see %s", run.outDir()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(run.report().collisions()).isZero();
        assertThat(run.report().minBattery()).isPositive();
    }

    /**
     * Larger robots (0.2 m and 0.3 m radius, generated with a scanner's fan of rays) among pillars,
     * in rooms and in clutter, with small noise: accomplished, never touching anything (with the
     * eight rays of earlier versions a 0.3 m robot met a thin pillar straight ahead, between its ±8° rays).
     */
    @ParameterizedTest(name = "{0} number {2}, radius {1} m, small noise")
    @CsvSource({"pillars, 0.3, 6", "pillars, 0.3, 9", "pillars, 0.2, 4", "rooms, 0.3, 2", "cluttered, 0.3, 5"})
    void largerRobotsAreAccomplishedWithoutTouchingAnything(String kind, double radiusM, int number) {
        WorldSpec world = new WorldGenerator(WorldGenerator.Kind.valueOf(kind.toUpperCase(java.util.Locale.ROOT)), radiusM)
                .world(17, number);
        assertThat(world.robot().sensorAnglesDeg()).hasSize(21).contains(0.0, -5.0, 5.0);
        Missions.Run run = Missions.direct(world, "safety-first", org.proactiverobotics.app.mission.NoiseLevel.SMALL);
        assertThat(run.report().outcome()).as("see %s", run.outDir()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(run.report().collisions()).isZero();
        assertThat(run.report().minBattery()).isPositive();
    }
}
