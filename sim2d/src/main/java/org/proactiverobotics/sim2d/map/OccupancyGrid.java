package org.proactiverobotics.sim2d.map;

import java.util.Objects;

/**
 * A map as cells that are free floor or blocked (occupied or unknown), square cells of one size, the
 * map's lower-left corner at a point of the world: what every map reader makes and {@link BoxCover}
 * turns into boxes. Column {@code i} grows along +x, row {@code j} along +y (row 0 is the image's
 * bottom row). Immutable.
 */
public final class OccupancyGrid {

    private final int columns;
    private final int rows;
    private final double cellM;
    private final double originX;
    private final double originY;
    private final boolean[] blocked;

    /**
     * @param columns cells along x, at least 1
     * @param rows    cells along y, at least 1
     * @param cellM   a cell's side, metres
     * @param originX x of the map's lower-left corner, metres
     * @param originY y of the map's lower-left corner, metres
     * @param blocked whether each cell is blocked, row by row from the bottom ({@code j * columns + i}); copied
     */
    public OccupancyGrid(int columns, int rows, double cellM, double originX, double originY, boolean[] blocked) {
        if (columns < 1 || rows < 1 || blocked.length != (long) columns * rows || !(cellM > 0)) {
            throw new IllegalArgumentException("a grid of " + columns + " x " + rows + " cells of " + cellM + " m with "
                    + blocked.length + " values");
        }
        this.columns = columns;
        this.rows = rows;
        this.cellM = cellM;
        this.originX = originX;
        this.originY = originY;
        this.blocked = blocked.clone();
    }

    /** @return cells along x */
    public int columns() {
        return columns;
    }

    /** @return cells along y */
    public int rows() {
        return rows;
    }

    /** @return a cell's side, metres */
    public double cellM() {
        return cellM;
    }

    /** @return x of the map's lower-left corner, metres */
    public double originX() {
        return originX;
    }

    /** @return y of the map's lower-left corner, metres */
    public double originY() {
        return originY;
    }

    /** @return the map's extent along x, metres (to the micrometre, as the boxes' edges) */
    public double widthM() {
        return micrometres(columns * cellM);
    }

    /** @return the map's extent along y, metres (to the micrometre) */
    public double heightM() {
        return micrometres(rows * cellM);
    }

    /** @return x of the map's centre, metres (to the micrometre) */
    public double centreX() {
        return micrometres(originX + columns * cellM / 2.0);
    }

    /** @return y of the map's centre, metres (to the micrometre) */
    public double centreY() {
        return micrometres(originY + rows * cellM / 2.0);
    }

    /** Rounds to micrometres: 12 cells of 0.4 m are 4.8 m in a world file, not 4.800000000000001. */
    static double micrometres(double v) {
        return Math.round(v * 1e6) / 1e6;
    }

    /** @return whether cell (i, j) is blocked; cells off the map count as blocked */
    public boolean blocked(int i, int j) {
        return i < 0 || j < 0 || i >= columns || j >= rows || blocked[j * columns + i];
    }

    /** @return how many cells are free floor */
    public int freeCells() {
        int n = 0;
        for (boolean b : blocked) {
            if (!b) {
                n++;
            }
        }
        return n;
    }

    /** @return how many free cells lie on the map's outer ring (the image's edge) */
    public int freeCellsOnEdge() {
        int n = 0;
        for (int i = 0; i < columns; i++) {
            n += !blocked(i, 0) ? 1 : 0;
            n += rows > 1 && !blocked(i, rows - 1) ? 1 : 0;
        }
        for (int j = 1; j < rows - 1; j++) {
            n += !blocked(0, j) ? 1 : 0;
            n += columns > 1 && !blocked(columns - 1, j) ? 1 : 0;
        }
        return n;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof OccupancyGrid g && g.columns == columns && g.rows == rows && g.cellM == cellM
                && g.originX == originX && g.originY == originY && java.util.Arrays.equals(g.blocked, blocked);
    }

    @Override
    public int hashCode() {
        return Objects.hash(columns, rows, cellM, originX, originY, java.util.Arrays.hashCode(blocked));
    }
}
