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

            @Override
            public synchronized List<MapChunk> readMap() {
                return new ArrayList<>(chunks.values());
            }

            @Override
            public synchronized void writeChunks(List<MapChunk> changed, long simTimeMs) {
                for (MapChunk c : changed) {
                    chunks.put(OccupancyMap.key(c.chunkX(), c.chunkY()), new MapChunk(c.chunkX(), c.chunkY(), c.cells().clone()));
                }
            }
        };
    }
}
