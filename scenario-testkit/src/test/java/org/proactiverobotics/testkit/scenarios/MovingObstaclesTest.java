package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.scenario.mapping.MappingScenario;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.testkit.ScenarioKit;

/**
 * The map and the routes with something that moves: scripted scans show an obstacle ahead, then
 * free rays through where it stood. A lone robot's map keeps it for good (two hits make a wall);
 * a robot that shares its world with others sees it go.
 */
class MovingObstaclesTest {

    private static final double RADIUS_M = 0.12;
    /** The front rays (±8°, ±20°) read an obstacle 0.5 m from the rim, the others nothing. */
    private static final double[] SOMETHING_AHEAD = {1, 1, 0.5, 0.5, 0.5, 0.5, 1, 1};
    private static final double[] NOTHING_AHEAD = {1, 1, 1, 1, 1, 1, 1, 1};

    private static OccupancyMap stored(ScenarioKit kit) {
        return OccupancyMap.of(new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID).readMap());
    }

    /** The cell where the +8° ray ends, the robot at the origin facing +x. */
    private static int[] hitCell() {
        double reach = RADIUS_M + 0.5;
        double a = Math.toRadians(8);
        return new int[] {OccupancyMap.cell(reach * Math.cos(a)), OccupancyMap.cell(reach * Math.sin(a))};
    }

    /** Shows the obstacle for {@code seen} steps, then free rays; returns the hit cell's evidence after each free step. */
    private static List<Integer> evidenceAfterItLeft(ScenarioKit.Builder builder, int seen, int freeSteps) {
        try (ScenarioKit kit = builder.builtIn(MappingScenario.NAME).start()) {
            kit.robot().gps(0, 0).headingDeg(0).scan(SOMETHING_AHEAD);
            kit.step(seen);
            int[] c = hitCell();
            List<Integer> evidence = new ArrayList<>();
            evidence.add(stored(kit).evidence(c[0], c[1]));
            kit.robot().scan(NOTHING_AHEAD);
            for (int s = 0; s < freeSteps; s++) {
                kit.step();
                evidence.add(stored(kit).evidence(c[0], c[1]));
            }
            return evidence;
        }
    }

    @Test
    void aLoneRobotsMapKeepsWhatItHitTwiceForGoodWhateverTheRaysSeeLater() {
        // what the evidence counting does for a lone robot: two hits make a wall, and walls stay
        List<Integer> evidence = evidenceAfterItLeft(ScenarioKit.builder(), 10, 20);
        assertThat(evidence.get(0)).isEqualTo(OccupancyMap.CONFIRMED);
        assertThat(evidence).allMatch(e -> e == OccupancyMap.CONFIRMED);
    }

    @Test
    void inASharedWorldACellAnObstacleLeftIsFreeAgainAfterAFewScansThroughIt() {
        List<Integer> evidence = evidenceAfterItLeft(ScenarioKit.builder().sharedWorld(), 10, 20);
        assertThat(evidence.get(0)).as("seen ten times: as much evidence as a wall").isEqualTo(OccupancyMap.CONFIRMED);
        // one ray through it per scan takes one away: free after six scans (0.2 s at 32 ms)
        assertThat(evidence.subList(0, 7)).containsExactly(6, 5, 4, 3, 2, 1, 0);
        assertThat(evidence).endsWith(0, 0);
    }

    @Test
    void inASharedWorldSomethingHitFromCloseByIsClearedToo() {
        try (ScenarioKit kit = ScenarioKit.builder().sharedWorld().builtIn(MappingScenario.NAME).start()) {
            kit.robot().gps(0, 0).headingDeg(0).scan(1, 1, 1, 0.15, 0.15, 1, 1, 1); // a robot right ahead: a wall for good at once
            kit.step(3);
            double reach = RADIUS_M + 0.15;
            int i = OccupancyMap.cell(reach * Math.cos(Math.toRadians(8)));
            int j = OccupancyMap.cell(reach * Math.sin(Math.toRadians(8)));
            assertThat(stored(kit).evidence(i, j)).isEqualTo(OccupancyMap.CONFIRMED);
            kit.robot().scan(NOTHING_AHEAD);
            kit.step(8);
            assertThat(stored(kit).get(i, j)).isEqualTo(OccupancyMap.FREE);
        }
    }

    @Test
    void inASharedWorldAWallTheRaysKeepHittingStays() {
        try (ScenarioKit kit = ScenarioKit.builder().sharedWorld().builtIn(MappingScenario.NAME).start()) {
            kit.robot().gps(0, 0).headingDeg(0).scan(SOMETHING_AHEAD);
            kit.step(40);
            int[] c = hitCell();
            assertThat(stored(kit).get(c[0], c[1])).isEqualTo(OccupancyMap.OCCUPIED);
            assertThat(stored(kit).evidence(c[0], c[1])).isEqualTo(OccupancyMap.CONFIRMED);
        }
    }

    /** Free rays ahead, then something moves in; the robot turns away for {@code awaySteps}: the hit cell's evidence then. */
    private static int evidenceOutOfViewAfterItMovedIn(ScenarioKit kit, int awaySteps) {
        kit.robot().gps(0, 0).headingDeg(0).scan(NOTHING_AHEAD); // the place seen free
        kit.step(3);
        kit.robot().scan(SOMETHING_AHEAD); // something there now
        kit.step(3);
        kit.robot().headingDeg(180).scan(NOTHING_AHEAD); // the robot looks the other way
        kit.step(awaySteps);
        int[] c = hitCell();
        return stored(kit).evidence(c[0], c[1]);
    }

    /* A wall's face that a grazing ray took free and the next ray hit again faded behind the robot, which went back to the
       same closed corridor end three times (issue 34, corridors-019 robot 1): touching a wall, it is the wall. */
    @Test
    void inASharedWorldWhatMovedInOnAWallsFaceIsKeptOutOfView() {
        try (ScenarioKit kit = ScenarioKit.builder().sharedWorld().builtIn(MappingScenario.NAME).start()) {
            // a wall for good right behind the hit cell, 0.85 m long: the hit cell is part of its face
            OccupancyMap map = OccupancyMap.empty();
            int[] c = hitCell();
            for (int j = c[1] - 8; j <= c[1] + 8; j++) {
                map.set(c[0] + 1, j, (byte) (OccupancyMap.FREE + OccupancyMap.CONFIRMED));
            }
            new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID).writeChunks(new ArrayList<MapChunk>(map.takeChanged()), 0);
            assertThat(evidenceOutOfViewAfterItMovedIn(kit, 60)).as("seen free, hit, touching the wall: kept out of view")
                    .isPositive();
            assertThat(evidenceOutOfViewAfterItMovedIn(kit, 60)).as("seen free and hit again: still kept").isPositive();
        }
    }

    @Test
    void inASharedWorldARobotSizedBodyThereAgainFadesAgain() {
        try (ScenarioKit kit = ScenarioKit.builder().sharedWorld().builtIn(MappingScenario.NAME).start()) {
            assertThat(evidenceOutOfViewAfterItMovedIn(kit, 60)).isZero();
            // alone, no wider than a robot: another robot that stood there again (at a checkpoint, in a door), not a wall
            assertThat(evidenceOutOfViewAfterItMovedIn(kit, 60)).as("there again: faded again").isZero();
        }
    }

    // ------------------------------------------------------------------ routes round a robot in a door

    /** A wall at y = 1 with two doors: x 0.9..1.5 (in front of the robot) and x 3.0..3.6. */
    private static void walls(ScenarioKit kit) {
        OccupancyMap map = OccupancyMap.empty();
        wall(map, -3, 1, 0.9);
        wall(map, 1.5, 1, 3.0);
        wall(map, 3.6, 1, 6);
        new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID).writeChunks(new ArrayList<MapChunk>(map.takeChanged()), 0);
    }

    private static void wall(OccupancyMap map, double x0, double y, double x1) {
        for (double x = x0; x <= x1 + 1e-9; x += OccupancyMap.CELL_M / 2) {
            // walls for good, as a lone robot's map has them after two hits
            map.set(OccupancyMap.cell(x), OccupancyMap.cell(y), (byte) (OccupancyMap.FREE + OccupancyMap.CONFIRMED));
        }
    }

    private static double turn(String drive) {
        String[] w = drive.split(" ");
        return Double.parseDouble(w[2]) - Double.parseDouble(w[1]); // right minus left: > 0 turns left
    }

    /** The robot at (1.2, 0.2) facing the door ahead; the checkpoint beyond it; something stands in the door. */
    private static List<Double> turnsWhileARobotStandsInTheDoorThenLeaves(ScenarioKit.Builder builder) {
        try (ScenarioKit kit = builder.builtIn(MappingScenario.NAME, ReachDestinationScenario.NAME).start()) {
            walls(kit);
            kit.mission().checkpoint(1.2, 2.5);
            kit.robot().gps(1.2, 0.2).headingDeg(90).scan(SOMETHING_AHEAD); // hits at y ≈ 0.81: in the door
            kit.step(10);
            List<Double> turns = new ArrayList<>();
            turns.add(turn(kit.suggestion(ReachDestinationScenario.NAME)));
            kit.robot().scan(NOTHING_AHEAD); // it left
            kit.step(2 * 64); // the route is planned afresh at least every 64 iterations
            turns.add(turn(kit.suggestion(ReachDestinationScenario.NAME)));
            return turns;
        }
    }

    @Test
    void inASharedWorldTheRouteGoesRoundARobotInTheDoorAndBackToTheShortWayOnceItLeft() {
        List<Double> turns = turnsWhileARobotStandsInTheDoorThenLeaves(ScenarioKit.builder().sharedWorld());
        assertThat(turns.get(0)).as("the door ahead taken: right, toward the other door at x = 3.3").isLessThan(-0.01);
        assertThat(turns.get(1)).as("the door free again: straight through it").isCloseTo(0.0, org.assertj.core.data.Offset.offset(0.01));
    }

    @Test
    void aLoneRobotKeepsGoingRoundWhatStoodInTheDoor() {
        List<Double> turns = turnsWhileARobotStandsInTheDoorThenLeaves(ScenarioKit.builder());
        assertThat(turns.get(0)).isLessThan(-0.01);
        assertThat(turns.get(1)).as("two hits made it a wall for good").isLessThan(-0.01);
    }
}
