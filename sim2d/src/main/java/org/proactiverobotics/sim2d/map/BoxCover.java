package org.proactiverobotics.sim2d.map;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Turns a map's blocked cells into few boxes that cover them exactly, so that a floor of thousands of
 * wall cells becomes hundreds or a few thousand bodies to simulate.
 * <p>
 * Greedy maximal rectangles: taking cells in order (rows from the bottom, left to right), each cell not
 * yet covered starts a box that grows right as far as blocked, uncovered cells go, then up for as long as
 * the whole next row of that span is blocked and uncovered. This is done once row-first and once
 * column-first, and the cover with fewer boxes is kept (row-first on a tie).
 * <p>
 * What it guarantees: every blocked cell lies in exactly one box, no box covers a free cell (the boxes
 * do not overlap and cover the blocked cells exactly), each box is as wide as it can be where it starts
 * and as tall as that width allows, and the result depends on the cells alone. It does not promise the
 * fewest boxes possible (a minimum partition needs a matching over the outline's concave corners);
 * docs/maps.md gives the counts it reaches on floor plans.
 */
public final class BoxCover {

    /**
     * A box of cells, inclusive bounds.
     *
     * @param i0 first column
     * @param j0 first row
     * @param i1 last column
     * @param j1 last row
     */
    public record Cells(int i0, int j0, int i1, int j1) {
    }

    private BoxCover() {
    }

    /**
     * @param grid the map
     * @return boxes covering exactly its blocked cells, in metres, axis-aligned
     */
    public static List<WorldSpec.Obstacle> boxes(OccupancyGrid grid) {
        List<WorldSpec.Obstacle> boxes = new ArrayList<>();
        double c = grid.cellM();
        for (Cells r : cells(grid)) {
            double x0 = grid.originX() + r.i0() * c;
            double x1 = grid.originX() + (r.i1() + 1) * c;
            double y0 = grid.originY() + r.j0() * c;
            double y1 = grid.originY() + (r.j1() + 1) * c;
            boxes.add(WorldSpec.Obstacle.box(OccupancyGrid.micrometres((x0 + x1) / 2), OccupancyGrid.micrometres((y0 + y1) / 2),
                    OccupancyGrid.micrometres(x1 - x0), OccupancyGrid.micrometres(y1 - y0), 0.0));
        }
        return boxes;
    }

    /**
     * @param grid the map
     * @return boxes of cells covering exactly its blocked cells, the fewer of the row-first and column-first covers
     */
    public static List<Cells> cells(OccupancyGrid grid) {
        int w = grid.columns();
        int h = grid.rows();
        // the two sweeps share nothing but the grid they read: the column-first one on another core meanwhile
        CompletableFuture<List<Cells>> byColumns = CompletableFuture.supplyAsync(() -> {
            boolean[] byColumn = new boolean[w * h];
            for (int i = 0; i < w; i++) {
                for (int j = 0; j < h; j++) {
                    byColumn[i * h + j] = grid.blocked(i, j); // transposed: the same sweep then runs up the columns first
                }
            }
            return greedy(byColumn, h, w);
        });
        boolean[] byRow = new boolean[w * h];
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                byRow[j * w + i] = grid.blocked(i, j);
            }
        }
        List<Cells> rowFirst = greedy(byRow, w, h);
        List<Cells> columnFirst = byColumns.join();
        if (columnFirst.size() < rowFirst.size()) {
            return columnFirst.stream().map(r -> new Cells(r.j0(), r.i0(), r.j1(), r.i1())).toList();
        }
        return rowFirst;
    }

    /** The sweep on a w x h grid (consumed): each uncovered cell starts a box, grown right, then up. */
    private static List<Cells> greedy(boolean[] todo, int w, int h) {
        List<Cells> out = new ArrayList<>();
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                if (!todo[j * w + i]) {
                    continue;
                }
                int i1 = i;
                while (i1 + 1 < w && todo[j * w + i1 + 1]) {
                    i1++;
                }
                int j1 = j;
                grow:
                while (j1 + 1 < h) {
                    int row = (j1 + 1) * w;
                    for (int k = i; k <= i1; k++) {
                        if (!todo[row + k]) {
                            break grow;
                        }
                    }
                    j1++;
                }
                for (int jj = j; jj <= j1; jj++) {
                    java.util.Arrays.fill(todo, jj * w + i, jj * w + i1 + 1, false);
                }
                out.add(new Cells(i, j, i1, j1));
            }
        }
        return out;
    }
}
