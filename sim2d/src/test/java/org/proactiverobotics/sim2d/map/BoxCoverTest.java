package org.proactiverobotics.sim2d.map;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.sim2d.WorldSpec;

/** The merged boxes cover a map's blocked cells exactly, one box a cell, none on the floor. */
class BoxCoverTest {

    @Test
    void randomMapsAreCoveredExactlyOnceAndTheSameMapGivesTheSameBoxes() {
        SplittableRandom random = new SplittableRandom(33);
        for (int n = 0; n < 40; n++) {
            int w = 1 + random.nextInt(40);
            int h = 1 + random.nextInt(30);
            boolean[] blocked = new boolean[w * h];
            double density = random.nextDouble();
            for (int k = 0; k < blocked.length; k++) {
                blocked[k] = random.nextDouble() < density;
            }
            for (int r = random.nextInt(6); r > 0; r--) { // a few solid blocks, as walls and furniture are
                int i0 = random.nextInt(w);
                int j0 = random.nextInt(h);
                for (int j = j0; j < Math.min(h, j0 + 1 + random.nextInt(10)); j++) {
                    for (int i = i0; i < Math.min(w, i0 + 1 + random.nextInt(10)); i++) {
                        blocked[j * w + i] = true;
                    }
                }
            }
            OccupancyGrid grid = new OccupancyGrid(w, h, 0.05, -1.3, 2.1, blocked);
            List<WorldSpec.Obstacle> boxes = BoxCover.boxes(grid);
            for (int j = 0; j < h; j++) {
                for (int i = 0; i < w; i++) {
                    double x = grid.originX() + (i + 0.5) * grid.cellM();
                    double y = grid.originY() + (j + 0.5) * grid.cellM();
                    long covering = boxes.stream().filter(b -> b.distanceTo(x, y) == 0.0).count();
                    assertThat(covering).as("map %d, cell (%d, %d)", n, i, j).isEqualTo(grid.blocked(i, j) ? 1 : 0);
                }
            }
            assertThat(boxes).isEqualTo(BoxCover.boxes(grid));
            int area = BoxCover.cells(grid).stream().mapToInt(c -> (c.i1() - c.i0() + 1) * (c.j1() - c.j0() + 1)).sum();
            assertThat(area).isEqualTo(w * h - grid.freeCells());
        }
    }

    @Test
    void aRoomsWallsBecomeFourBoxesAndAColumnOfWallOneWhicheverWayItRuns() {
        int w = 60;
        int h = 40;
        boolean[] ring = new boolean[w * h];
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                ring[j * w + i] = i < 2 || j < 2 || i >= w - 2 || j >= h - 2;
            }
        }
        assertThat(BoxCover.cells(new OccupancyGrid(w, h, 0.05, 0, 0, ring))).hasSize(4);
        boolean[] column = new boolean[w * h];
        for (int j = 0; j < h; j++) {
            column[j * w + 30] = true;
            column[j * w + 31] = true;
        }
        List<WorldSpec.Obstacle> one = BoxCover.boxes(new OccupancyGrid(w, h, 0.05, 0, 0, column));
        assertThat(one).containsExactly(WorldSpec.Obstacle.box(1.55, 1.0, 0.1, 2.0, 0.0));
    }
}
