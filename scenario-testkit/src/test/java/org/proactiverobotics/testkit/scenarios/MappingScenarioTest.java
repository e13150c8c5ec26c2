package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.scenario.mapping.MappingScenario;
import org.proactiverobotics.engine.scenario.mapping.UpdateMap;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.testkit.ScenarioKit;

/** The Mapping scenario alone: a scripted scan marks cells in the shared occupancy_map rows. */
class MappingScenarioTest {

    private static ScenarioKit kit() {
        return ScenarioKit.builder().builtIn(MappingScenario.NAME).start();
    }

    private static OccupancyMap stored(ScenarioKit kit) {
        return OccupancyMap.of(new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID).readMap());
    }

    private static byte cellAt(OccupancyMap map, double x, double y) {
        return map.get(OccupancyMap.cell(x), OccupancyMap.cell(y));
    }

    @Test
    void aScanMarksTheCellsItsRaysCrossedFreeAndWhereTheyHitOccupied() {
        try (ScenarioKit kit = kit()) {
            // facing +x; the sensor at +8° reads an obstacle 0.5 m from the rim (radius 0.12 m), the others nothing
            kit.robot().gps(0, 0).headingDeg(0).scan(1, 1, 1, 1, 0.5, 1, 1, 1);
            kit.step(3);
            double hit = 0.12 + 0.5;
            double a = Math.toRadians(8);
            OccupancyMap map = stored(kit); // every chunk the scan changed is written in its iteration
            assertThat(cellAt(map, hit * Math.cos(a), hit * Math.sin(a))).as("where the ray hit").isEqualTo(OccupancyMap.OCCUPIED);
            assertThat(cellAt(map, 0.3 * Math.cos(a), 0.3 * Math.sin(a))).as("on the ray, before the hit").isEqualTo(OccupancyMap.FREE);
            assertThat(cellAt(map, 0, -0.9)).as("the free ray at -90°, within range + radius").isEqualTo(OccupancyMap.FREE);
            assertThat(cellAt(map, 0, 1.0)).as("the free ray at +90° ends at the range: its last cell is free").isEqualTo(OccupancyMap.FREE);
            assertThat(cellAt(map, 0, 1.3)).as("beyond the range").isEqualTo(OccupancyMap.UNKNOWN);
            assertThat(cellAt(map, -0.5, 0)).as("behind the robot: no ray").isEqualTo(OccupancyMap.UNKNOWN);
            assertThat(map.occupiedCells()).isEqualTo(1);
            assertThat(kit.engine().slots()).as("it suggests nothing: no CommandArray slot").doesNotContainKey(MappingScenario.NAME);
        }
    }

    @Test
    void onlyTheChunksAScanChangesAreWritten() throws Exception {
        try (ScenarioKit kit = kit()) {
            // facing +y from the middle of chunk (0, 0); the sensor at -8° hits 0.3 m from the rim, in the same chunk
            kit.robot().gps(0.4, 0.2).headingDeg(90).scan(1, 1, 1, 0.3, 1, 1, 1, 1);
            kit.step(3);
            Map<String, Long> first = rowTimes(kit);
            assertThat(first).containsKey("0,0").hasSizeGreaterThan(1); // the hit's chunk and those the free rays crossed
            kit.step(3); // the same scan from the same place: nothing changes, nothing is written
            assertThat(rowTimes(kit)).isEqualTo(first);
        }
    }

    @Test
    void aScanWithoutAPoseOfTheSameMomentMarksNothing() {
        try (ScenarioKit kit = kit()) {
            kit.robot().scan(0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3); // no GPS nor heading yet
            kit.step(3);
            assertThat(stored(kit).isEmpty()).isTrue();
        }
    }

    private static Map<String, Long> rowTimes(ScenarioKit kit) throws Exception {
        Map<String, Long> out = new HashMap<>();
        try (Connection c = kit.database().getConnection(); PreparedStatement ps = c.prepareStatement(
                "SELECT chunk_x, chunk_y, updated_sim_time_ms FROM occupancy_map WHERE robot_id = ?")) {
            ps.setInt(1, ScenarioKit.ROBOT_ID);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    out.put(rs.getInt(1) + "," + rs.getInt(2), rs.getLong(3));
                }
            }
        }
        return out;
    }
}
