package org.proactiverobotics.app.foxglove;

import java.util.Base64;
import java.util.HashMap;
import java.util.Map;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * The engine's occupancy map rebuilt from its deltas (cells of {@link OccupancyMap#CELL_M} m, state
 * 0 unknown, 1 free, 2 occupied), written as a foxglove.Grid over the bounding box of the cells
 * known so far.
 */
final class MapGrid {

    private final Map<Long, Byte> cells = new HashMap<>();
    private int minX = Integer.MAX_VALUE;
    private int minY = Integer.MAX_VALUE;
    private int maxX = Integer.MIN_VALUE;
    private int maxY = Integer.MIN_VALUE;

    /**
     * @param delta cells as {ix, iy, state, ix, iy, state, ...} (trace.jsonl's mapDelta, flat)
     * @return whether any cell changed
     */
    boolean apply(int[] delta) {
        boolean changed = false;
        for (int k = 0; k + 2 < delta.length; k += 3) {
            int ix = delta[k];
            int iy = delta[k + 1];
            int state = delta[k + 2];
            Byte before = cells.put(key(ix, iy), (byte) state);
            changed |= before == null ? state != OccupancyMap.UNKNOWN : before != state;
            minX = Math.min(minX, ix);
            minY = Math.min(minY, iy);
            maxX = Math.max(maxX, ix);
            maxY = Math.max(maxY, iy);
        }
        return changed;
    }

    /** Writes the grid message (nothing known yet: a 0 × 0 grid). */
    void write(JsonText j, long simTimeMs) {
        int w = cells.isEmpty() ? 0 : maxX - minX + 1;
        int h = cells.isEmpty() ? 0 : maxY - minY + 1;
        byte[] data = new byte[w * h];
        cells.forEach((k, v) -> data[(int) ((k >> 32) - minY) * w + (int) (k.intValue() - minX)] = v);
        j.begin().open().name("timestamp").time(simTimeMs).name("frame_id").string("world");
        j.name("pose");
        Scene.pose(j, cells.isEmpty() ? 0 : minX * OccupancyMap.CELL_M, cells.isEmpty() ? 0 : minY * OccupancyMap.CELL_M, 0, 0);
        j.name("column_count").integer(w);
        j.name("cell_size").open().name("x").number(OccupancyMap.CELL_M, 3).name("y").number(OccupancyMap.CELL_M, 3).close();
        j.name("row_stride").integer(w).name("cell_stride").integer(1);
        j.name("fields").openArray().open().name("name").string("state").name("offset").integer(0).name("type").integer(1)
                .close().closeArray();
        j.name("data").string(Base64.getEncoder().encodeToString(data));
        j.close().end();
    }

    private static long key(int ix, int iy) {
        return ((long) iy << 32) | (ix & 0xFFFFFFFFL);
    }
}
