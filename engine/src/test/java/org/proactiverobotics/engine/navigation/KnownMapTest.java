package org.proactiverobotics.engine.navigation;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.OccupancyMapTable;

class KnownMapTest {

    /** The in-memory map table, its reads counted and its writes able to fail. */
    private static final class Rows implements OccupancyMapTable {
        final OccupancyMapTable rows = OccupancyMapTable.inMemory();
        final AtomicInteger reads = new AtomicInteger();
        final AtomicBoolean failWrites = new AtomicBoolean();

        @Override
        public List<MapChunk> readMap() {
            reads.incrementAndGet();
            return rows.readMap();
        }

        @Override
        public List<MapChunk> readMapSince(long simTimeMs) {
            reads.incrementAndGet();
            return rows.readMapSince(simTimeMs);
        }

        @Override
        public void writeChunks(List<MapChunk> chunks, long simTimeMs) {
            rows.writeChunks(chunks, simTimeMs);
            if (failWrites.get()) {
                throw new IllegalStateException("connection lost after the write");
            }
        }
    }

    private static List<MapChunk> occupied(int i, int j) {
        OccupancyMap scratch = OccupancyMap.empty();
        scratch.set(i, j, OccupancyMap.OCCUPIED);
        return scratch.takeChanged();
    }

    @Test
    void whatItsRulesWriteIsInTheNextIterationsMapWithoutReadingItBack() {
        Rows rows = new Rows();
        rows.writeChunks(occupied(3, 4), 0); // drawn before this engine started (another engine, a resume)
        KnownMap known = new KnownMap(rows);
        OccupancyMap first = known.current(1, 32);
        assertThat(first.get(3, 4)).isEqualTo(OccupancyMap.OCCUPIED);
        assertThat(rows.reads).hasValue(1);

        known.table().writeChunks(occupied(40, -7), 64);
        assertThat(known.current(1, 64)).as("the same map for the whole iteration").isSameAs(first);
        assertThat(first.get(40, -7)).isNotEqualTo(OccupancyMap.OCCUPIED);

        OccupancyMap second = known.current(2, 96);
        assertThat(second.get(40, -7)).isEqualTo(OccupancyMap.OCCUPIED);
        assertThat(second.get(3, 4)).isEqualTo(OccupancyMap.OCCUPIED);
        assertThat(rows.reads).as("no read after the first").hasValue(1);
        assertThat(OccupancyMap.of(rows.rows.readMap()).get(40, -7)).as("and the table has it").isEqualTo(OccupancyMap.OCCUPIED);
    }

    @Test
    void afterAFailedWriteTheNextIterationReadsTheTableBack() {
        Rows rows = new Rows();
        KnownMap known = new KnownMap(rows);
        known.current(1, 1000);
        rows.failWrites.set(true);
        assertThatThrownBy(() -> known.table().writeChunks(occupied(5, 5), 1000)).isInstanceOf(IllegalStateException.class);
        rows.failWrites.set(false);
        assertThat(known.current(2, 1032).get(5, 5)).as("the write reached the table: read back").isEqualTo(OccupancyMap.OCCUPIED);
        assertThat(rows.reads).hasValue(2);
        known.current(3, 1064);
        assertThat(rows.reads).as("and not again").hasValue(2);
    }

    @Test
    void forgetReadsTheRowsWholeAgain() {
        Rows rows = new Rows();
        KnownMap known = new KnownMap(rows);
        known.current(1, 0);
        known.table().writeChunks(occupied(1, 1), 32);
        known.forget();
        rows.rows.writeChunks(occupied(200, 200), 64); // what another engine drew while this one was away
        OccupancyMap map = known.current(1, 64);
        assertThat(map.get(1, 1)).isEqualTo(OccupancyMap.OCCUPIED);
        assertThat(map.get(200, 200)).isEqualTo(OccupancyMap.OCCUPIED);
        assertThat(rows.reads).hasValue(2);
    }
}
