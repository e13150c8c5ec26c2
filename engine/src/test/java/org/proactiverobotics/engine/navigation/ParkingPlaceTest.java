package org.proactiverobotics.engine.navigation;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.OccupancyMap;

/** A robot that is done parks out of a gap's mouth, and where it wants to be when that closes no way. */
class ParkingPlaceTest {

    private static final double RADIUS_M = 0.12;
    /** Half the side of the closed box, cells (2.5 m). */
    private static final int BOX = 50;

    /**
     * A closed box, seen free inside, with a wall across it at row 0 and one gap of {@code gapCells}
     * cells from column 0: the only way between the two halves.
     */
    private static OccupancyMap boxWithGap(int gapCells) {
        OccupancyMap map = OccupancyMap.empty();
        for (int j = -BOX; j <= BOX; j++) {
            for (int i = -BOX; i <= BOX; i++) {
                boolean wall = Math.abs(i) == BOX || Math.abs(j) == BOX || j == 0 && (i < 0 || i >= gapCells);
                map.set(i, j, wall ? OccupancyMap.OCCUPIED : OccupancyMap.FREE);
            }
        }
        return map;
    }

    @Test
    void aStartInTheGapsMouthParksWhereOneCanGoRound() {
        OccupancyMap map = boxWithGap(10); // 0.5 m, as the generated worlds' doors
        double gapX = OccupancyMap.centre(5);
        double[] place = ParkingPlace.near(map, gapX, 0.2, RADIUS_M);
        double fromGap = Math.hypot(place[0] - gapX, place[1]);
        assertThat(fromGap).as("out of the mouth: another robot's body passes between it and the gap")
                .isGreaterThan(2 * RADIUS_M + 0.2);
        assertThat(place[1]).as("on the start's side").isPositive();
        assertThat(fromGap).as("still near the start").isLessThan(1.2);
    }

    @Test
    void aStartInTheOpenIsKept() {
        OccupancyMap map = boxWithGap(10);
        double[] place = ParkingPlace.near(map, 1.0, 1.2, RADIUS_M);
        assertThat(place[0]).isEqualTo(OccupancyMap.centre(OccupancyMap.cell(1.0)));
        assertThat(place[1]).isEqualTo(OccupancyMap.centre(OccupancyMap.cell(1.2)));
    }

    @Test
    void aStartAgainstALongWallIsKeptTheWayStaysOpenBeside() {
        OccupancyMap map = boxWithGap(10);
        // 0.25 m from the wall across, 1.5 m from the gap: one can go round on the other side
        double[] place = ParkingPlace.near(map, -1.5, 0.25, RADIUS_M);
        assertThat(Math.hypot(place[0] + 1.5, place[1] - 0.25)).isLessThan(0.1);
    }
}
