package org.proactiverobotics.engine.navigation;

import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.OccupancyMapTable;

/**
 * The occupancy map as the engine knows it, for every rule that plans on it: read whole on first
 * use, then once per iteration only the chunks written since (the mapping scenario writes the
 * chunks a scan changed, stamped with the scan's time). An engine service, one per robot.
 */
public final class KnownMap {

    /** Chunks stamped this long before the last refresh's time are read again (readings of one moment differ by a few ms). */
    static final long OVERLAP_MS = 1000;

    private final OccupancyMapTable table;
    private OccupancyMap map;
    private long refreshedIteration = -1;
    private long refreshedAtMs;

    /** @param table the map's rows */
    public KnownMap(OccupancyMapTable table) {
        this.table = table;
    }

    /** Forgets the map held: the next use reads the rows whole (after a start, a resume, or rows deleted for a new robot run). */
    public synchronized void forget() {
        map = null;
        refreshedIteration = -1;
    }

    /**
     * @param iteration the engine's iteration
     * @param nowMs     the simulated time of the newest reading the caller has, milliseconds
     * @return the map with every chunk written so far; the same object for the whole iteration
     */
    public synchronized OccupancyMap current(long iteration, long nowMs) {
        if (map == null) {
            map = OccupancyMap.of(table.readMap());
        } else if (iteration != refreshedIteration) {
            map.putAll(table.readMapSince(refreshedAtMs - OVERLAP_MS));
        } else {
            return map;
        }
        refreshedIteration = iteration;
        refreshedAtMs = nowMs;
        return map;
    }
}
