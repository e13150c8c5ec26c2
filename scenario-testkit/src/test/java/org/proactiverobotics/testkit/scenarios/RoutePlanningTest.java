package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.testkit.ScenarioKit;

/** ReachDestination on a map written into occupancy_map: it follows the route, and gives up on a walled-in checkpoint. */
class RoutePlanningTest {

    private static final String DESTINATION = ReachDestinationScenario.NAME;

    private static ScenarioKit kit() {
        return ScenarioKit.builder().builtIn(DESTINATION).start();
    }

    /** Occupied cells along a segment, written as the Mapping scenario would. */
    private static void wall(OccupancyMap map, double x0, double y0, double x1, double y1) {
        int n = (int) Math.ceil(Math.hypot(x1 - x0, y1 - y0) / (OccupancyMap.CELL_M / 2));
        for (int k = 0; k <= n; k++) {
            double t = (double) k / n;
            map.set(OccupancyMap.cell(x0 + t * (x1 - x0)), OccupancyMap.cell(y0 + t * (y1 - y0)), OccupancyMap.OCCUPIED);
        }
    }

    private static void store(ScenarioKit kit, OccupancyMap map) {
        List<MapChunk> chunks = new ArrayList<>(map.takeChanged());
        new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID).writeChunks(chunks, 0);
    }

    private static double turn(String drive) {
        String[] w = drive.split(" ");
        return Double.parseDouble(w[2]) - Double.parseDouble(w[1]); // right minus left: > 0 turns left
    }

    @Test
    void aWallAcrossTheWayMakesItSteerForTheDoorInsteadOfStraightAtTheCheckpoint() {
        try (ScenarioKit kit = kit()) {
            OccupancyMap map = OccupancyMap.empty();
            wall(map, -3, 1, 0.9, 1); // a wall at y = 1 with a 0.6 m door from x = 0.9 to 1.5
            wall(map, 1.5, 1, 4, 1);
            store(kit, map);
            kit.mission().checkpoint(0, 2.5);
            kit.robot().gps(0, 0).headingDeg(90); // facing the checkpoint, straight through the wall
            kit.step(3);
            assertThat(turn(kit.suggestion(DESTINATION))).as("turns right, toward the door at x = 1.2").isLessThan(0);
        }
    }

    @Test
    void aWalledInCheckpointIsMarkedUnreachableAndTheRobotStops() {
        try (ScenarioKit kit = kit()) {
            OccupancyMap map = OccupancyMap.empty();
            wall(map, 1, 1, 3, 1); // a closed box around the checkpoint at (2, 2)
            wall(map, 3, 1, 3, 3);
            wall(map, 3, 3, 1, 3);
            wall(map, 1, 3, 1, 1);
            store(kit, map);
            kit.mission().checkpoint(2, 2);
            kit.robot().gps(0, 0).headingDeg(0);
            kit.step(2 + 32); // a second without a route: the robot waits, scanning (a noisy reading may have drawn the wall)
            JdbcRobotTables tables = new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID);
            assertThat(tables.checkpoints()).extracting(Checkpoint::unreachable).containsExactly(false);
            assertThat(kit.suggestion(DESTINATION)).isEqualTo("STOP");
            kit.step(3 * 32); // three seconds without a route: unreachable
            assertThat(tables.checkpoints()).extracting(Checkpoint::unreachable).containsExactly(true);
            kit.step(2);
            assertThat(kit.suggestion(DESTINATION)).isEqualTo("STOP");
            assertThat(kit.reachedCheckpoints()).isEmpty();
        }
    }

    @Test
    void aBoxWithADoorIsNotUnreachable() {
        try (ScenarioKit kit = kit()) {
            OccupancyMap map = OccupancyMap.empty();
            wall(map, 1, 1, 1.7, 1); // the same box with a 0.6 m door in its lower side
            wall(map, 2.3, 1, 3, 1);
            wall(map, 3, 1, 3, 3);
            wall(map, 3, 3, 1, 3);
            wall(map, 1, 3, 1, 1);
            store(kit, map);
            kit.mission().checkpoint(2, 2);
            kit.robot().gps(0, 0).headingDeg(0);
            kit.step(2 + 4 * 16);
            JdbcRobotTables tables = new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID);
            assertThat(tables.checkpoints()).extracting(Checkpoint::unreachable).containsExactly(false);
            assertThat(kit.suggestion(DESTINATION)).startsWith("DRIVE");
        }
    }
}
