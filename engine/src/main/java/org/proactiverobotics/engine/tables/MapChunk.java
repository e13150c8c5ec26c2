package org.proactiverobotics.engine.tables;

import java.util.Arrays;

/**
 * One {@code occupancy_map} row: a square of {@value OccupancyMap#CHUNK_CELLS} ×
 * {@value OccupancyMap#CHUNK_CELLS} cells of {@value OccupancyMap#CELL_M} m, row by row from
 * its lower-left corner, one byte per cell ({@link OccupancyMap#UNKNOWN}, {@link OccupancyMap#FREE},
 * {@link OccupancyMap#OCCUPIED}).
 *
 * @param chunkX the chunk's column: its cells start at x = chunkX × chunk size, metres
 * @param chunkY the chunk's row
 * @param cells  the cells, {@code CHUNK_CELLS²} bytes
 */
public record MapChunk(int chunkX, int chunkY, byte[] cells) {

    /** Checks the size. */
    public MapChunk {
        if (cells.length != OccupancyMap.CHUNK_CELLS * OccupancyMap.CHUNK_CELLS) {
            throw new IllegalArgumentException("a map chunk has " + OccupancyMap.CHUNK_CELLS * OccupancyMap.CHUNK_CELLS
                    + " cells, not " + cells.length);
        }
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof MapChunk c && c.chunkX == chunkX && c.chunkY == chunkY && Arrays.equals(c.cells, cells);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * chunkX + chunkY) + Arrays.hashCode(cells);
    }

    @Override
    public String toString() {
        return "MapChunk[" + chunkX + ", " + chunkY + "]";
    }
}
