package org.proactiverobotics.engine.tables;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The robot's occupancy map as shared rows ({@code occupancy_map}): the mapping scenario writes
 * the chunks it changed, any scenario (or another process) reads them.
 */
public interface OccupancyMapTable {

    /** @return every stored chunk of this robot's map */
    List<MapChunk> readMap();

    /**
     * @param simTimeMs a simulated time, milliseconds
     * @return at least every chunk written with readings of that time or later (all of them, unless
     *         the table can tell)
     */
    default List<MapChunk> readMapSince(long simTimeMs) {
        return readMap();
    }

    /**
     * Stores chunks, replacing the stored ones at the same place.
     *
     * @param chunks    the chunks that changed
     * @param simTimeMs the simulated time of the newest reading they include, milliseconds
     */
    void writeChunks(List<MapChunk> chunks, long simTimeMs);

    /**
     * A map kept in memory only: for a communication layer that has no map rows (a benchmark's
     * or a test's own tables), so that the scenarios that read the map still run.
     *
     * @return an empty map table
     */
    static OccupancyMapTable inMemory() {
        return new OccupancyMapTable() {
            private final Map<Long, MapChunk> chunks = new TreeMap<>();
            private final Map<Long, Long> written = new TreeMap<>();

            @Override
            public synchronized List<MapChunk> readMap() {
                return new ArrayList<>(chunks.values());
            }

            @Override
            public synchronized List<MapChunk> readMapSince(long simTimeMs) {
                List<MapChunk> out = new ArrayList<>();
                chunks.forEach((k, c) -> {
                    if (written.get(k) >= simTimeMs) {
                        out.add(c);
                    }
                });
                return out;
            }

            @Override
            public synchronized void writeChunks(List<MapChunk> changed, long simTimeMs) {
                for (MapChunk c : changed) {
                    long k = OccupancyMap.key(c.chunkX(), c.chunkY());
                    chunks.put(k, new MapChunk(c.chunkX(), c.chunkY(), c.cells().clone()));
                    written.put(k, simTimeMs);
                }
            }
        };
    }
}
