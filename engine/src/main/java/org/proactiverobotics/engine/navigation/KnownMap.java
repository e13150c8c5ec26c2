package org.proactiverobotics.engine.navigation;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.OccupancyMapTable;

/**
 * The occupancy map as the engine knows it, for every rule that plans on it: read whole on first
 * use (after a start or a resume: another engine may have drawn it), then brought up to date once
 * per iteration with the chunks written since. This engine is the only writer of its robot's map
 * (the robot's lease), so the chunks its rules write through {@link #table()} are kept as they are
 * written rather than read back from the database at every iteration. An engine service, one per robot.
 */
public final class KnownMap {

    /** After a failed write, chunks stamped this long before the last refresh's time are read back (readings of one moment differ by a few ms). */
    static final long OVERLAP_MS = 1000;

    private final OccupancyMapTable table;
    private final OccupancyMapTable writer;
    private OccupancyMap map;
    private long refreshedIteration = -1;
    private long refreshedAtMs;
    /** The chunks written since the last refresh, newest content per place. */
    private final Map<Long, MapChunk> written = new LinkedHashMap<>();
    /** A write failed part way: what reached the table is not known, so the next refresh reads it back. */
    private boolean readBack;

    /** @param table the map's rows */
    public KnownMap(OccupancyMapTable table) {
        this.table = table;
        this.writer = new OccupancyMapTable() {
            @Override
            public List<MapChunk> readMap() {
                return table.readMap();
            }

            @Override
            public List<MapChunk> readMapSince(long simTimeMs) {
                return table.readMapSince(simTimeMs);
            }

            @Override
            public void writeChunks(List<MapChunk> chunks, long simTimeMs) {
                try {
                    table.writeChunks(chunks, simTimeMs);
                } catch (RuntimeException e) {
                    failedWrite();
                    throw e;
                }
                wrote(chunks);
            }
        };
    }

    /** @return the map's rows, for the rules that write them: what is written here is part of the next refresh */
    public OccupancyMapTable table() {
        return writer;
    }

    /** Forgets the map held: the next use reads the rows whole (after a start, a resume, or rows deleted for a new robot run). */
    public synchronized void forget() {
        map = null;
        refreshedIteration = -1;
        written.clear();
        readBack = false;
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
            if (readBack) {
                map.putAll(table.readMapSince(refreshedAtMs - OVERLAP_MS));
            }
            map.putAll(new ArrayList<>(written.values()));
        } else {
            return map;
        }
        written.clear();
        readBack = false;
        refreshedIteration = iteration;
        refreshedAtMs = nowMs;
        return map;
    }

    private synchronized void wrote(List<MapChunk> chunks) {
        for (MapChunk c : chunks) {
            written.put(((long) c.chunkX() << 32) ^ (c.chunkY() & 0xffffffffL), new MapChunk(c.chunkX(), c.chunkY(), c.cells().clone()));
        }
    }

    private synchronized void failedWrite() {
        readBack = true;
    }
}
