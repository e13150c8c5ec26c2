package org.proactiverobotics.engine.tables;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

class OccupancyMapTest {

    @Test
    void cellsSetAnywhereReadBackWhateverOrderTheMapGrewIn() {
        OccupancyMap map = OccupancyMap.empty();
        Map<Long, Byte> expected = new HashMap<>();
        Random random = new Random(7);
        for (int n = 0; n < 5000; n++) {
            // negative and positive indices, chunks on diagonals (whose Long keys used to collide)
            int i = random.nextInt(2000) - 1000;
            int j = random.nextInt(2000) - 1000;
            byte state = (byte) (1 + random.nextInt(2));
            map.set(i, j, state);
            expected.put(OccupancyMap.key(i, j), state);
        }
        expected.forEach((k, state) -> assertThat(map.get((int) (k >> 32), (int) (long) k)).isEqualTo(state));
        assertThat(map.get(5000, -5000)).isEqualTo(OccupancyMap.UNKNOWN);
        assertThat(map.occupiedCells()).isEqualTo((int) expected.values().stream().filter(s -> s == OccupancyMap.OCCUPIED).count());
        assertThat(map.minCell(true)).isLessThanOrEqualTo(-1000);
        assertThat(map.maxCellExclusive(true)).isGreaterThan(999);
    }

    /**
     * Issue 33: the map counts its occupied chunks per block of 6.4 m, so that a look along a long line
     * passes an empty stretch at once: a box holding an occupied cell is never passed, whichever way
     * the map grew; a box far from every one is; cells cleared again leave their blocks empty.
     */
    @Test
    void occupiedBlocksFollowTheCellsAsTheyComeAndGoAndAsTheMapGrows() {
        OccupancyMap map = OccupancyMap.empty();
        Random random = new Random(11);
        List<int[]> occupied = new ArrayList<>();
        for (int n = 0; n < 400; n++) {
            // cells far apart on every side: the array grows, and its origin moves, many times
            int i = random.nextInt(4000) - 2000;
            int j = random.nextInt(4000) - 2000;
            map.set(i, j, random.nextBoolean() ? OccupancyMap.OCCUPIED : OccupancyMap.FREE);
            if (map.get(i, j) == OccupancyMap.OCCUPIED) {
                occupied.add(new int[] {i, j});
            }
        }
        for (int[] c : occupied) {
            double x = OccupancyMap.centre(c[0]);
            double y = OccupancyMap.centre(c[1]);
            assertThat(map.occupiedBlockIn(x - 0.01, y - 0.01, x + 0.01, y + 0.01)).isTrue();
        }
        assertThat(map.occupiedBlockIn(300, 300, 310, 310)).as("far beyond every cell").isFalse();
        for (int[] c : occupied) {
            map.set(c[0], c[1], OccupancyMap.FREE);
        }
        for (int[] c : occupied) {
            double x = OccupancyMap.centre(c[0]);
            double y = OccupancyMap.centre(c[1]);
            assertThat(map.occupiedBlockIn(x - 1, y - 1, x + 1, y + 1)).as("cleared").isFalse();
        }
    }

    /** occupiedApproached, read chunk by chunk, answers as a look at every cell of its box does. */
    @Test
    void anApproachedWallIsFoundAsALookAtEveryCellFindsIt() {
        OccupancyMap map = OccupancyMap.empty();
        Random random = new Random(3);
        for (int n = 0; n < 300; n++) {
            map.set(random.nextInt(80) - 40, random.nextInt(80) - 40, OccupancyMap.OCCUPIED);
        }
        int found = 0;
        for (int trial = 0; trial < 2000; trial++) {
            double px = random.nextDouble() * 4 - 2;
            double py = random.nextDouble() * 4 - 2;
            double fromX = px + random.nextGaussian() * 0.1;
            double fromY = py + random.nextGaussian() * 0.1;
            double keepM = 0.05 + random.nextDouble() * 0.3;
            boolean expected = false;
            for (int j = OccupancyMap.cell(py - keepM); j <= OccupancyMap.cell(py + keepM); j++) {
                for (int i = OccupancyMap.cell(px - keepM); i <= OccupancyMap.cell(px + keepM); i++) {
                    double cx = OccupancyMap.centre(i);
                    double cy = OccupancyMap.centre(j);
                    double d2 = (cx - px) * (cx - px) + (cy - py) * (cy - py);
                    expected |= d2 < keepM * keepM && d2 < (cx - fromX) * (cx - fromX) + (cy - fromY) * (cy - fromY) - 1e-6
                            && map.get(i, j) == OccupancyMap.OCCUPIED;
                }
            }
            assertThat(map.occupiedApproached(fromX, fromY, px, py, keepM)).as("trial %d", trial).isEqualTo(expected);
            found += expected ? 1 : 0;
        }
        assertThat(found).isBetween(200, 1800);
    }

    @Test
    void changedChunksRebuildTheSameMapAndTheOccupiedCellsAreVisitedOnce() {
        OccupancyMap map = OccupancyMap.empty();
        map.set(-1, -1, OccupancyMap.OCCUPIED);
        map.set(40, 3, OccupancyMap.OCCUPIED);
        map.set(40, 4, OccupancyMap.FREE);
        map.set(-300, 200, OccupancyMap.OCCUPIED);
        List<MapChunk> chunks = map.takeChanged();
        assertThat(chunks).hasSize(3);
        assertThat(map.takeChanged()).isEmpty();

        OccupancyMap copy = OccupancyMap.of(chunks);
        List<String> visited = new ArrayList<>();
        copy.forEachOccupied((i, j) -> visited.add(i + "," + j));
        assertThat(visited).containsExactlyInAnyOrder("-1,-1", "40,3", "-300,200");
        assertThat(copy.get(40, 4)).isEqualTo(OccupancyMap.FREE);
        assertThat(copy.occupiedWithin(OccupancyMap.centre(40), OccupancyMap.centre(3) + 0.06, 0.07)).isTrue();
        assertThat(copy.occupiedWithin(OccupancyMap.centre(40), OccupancyMap.centre(3) + 0.06, 0.05)).isFalse();
    }

    @Test
    void aLongCorridorGrowsOneAxisAndAChunkFarAwayOnBothIsRefusedWithItsPlace() {
        OccupancyMap map = OccupancyMap.empty();
        for (int i = 0; i < 40_000; i += 7) { // a straight 2 km drive east
            map.set(i, 3, OccupancyMap.FREE);
        }
        assertThat(map.get(39_998, 3)).isEqualTo(OccupancyMap.FREE);
        assertThatThrownBy(() -> map.set(-10_000_000, 10_000_000, OccupancyMap.OCCUPIED))
                .isInstanceOf(IllegalStateException.class).hasMessageContaining("too far away");
        assertThat(map.get(0, 3)).isEqualTo(OccupancyMap.FREE);
    }

    @Test
    void aWallSeenOnceIsClearedByTheRaysThatPassThroughItOneSeenTwiceOrFromCloseByStays() {
        OccupancyMap map = OccupancyMap.empty();
        map.hit(0, 0); // a noisy reading drew a wall here
        assertThat(map.get(0, 0)).isEqualTo(OccupancyMap.OCCUPIED);
        for (int n = 1; n < OccupancyMap.HIT / OccupancyMap.MISS; n++) {
            map.miss(0, 0);
            assertThat(map.get(0, 0)).as("after %d rays through it", n).isEqualTo(OccupancyMap.OCCUPIED);
        }
        map.miss(0, 0);
        assertThat(map.get(0, 0)).as("every passing ray took some evidence away").isEqualTo(OccupancyMap.FREE);

        map.hit(5, 5);
        map.hit(5, 5); // seen twice: a wall
        assertThat(map.evidence(5, 5)).isEqualTo(OccupancyMap.CONFIRMED);
        for (int n = 0; n < 100; n++) {
            map.miss(5, 5); // rays grazing it
        }
        assertThat(map.get(5, 5)).isEqualTo(OccupancyMap.OCCUPIED);

        map.confirm(9, 9); // hit from close by
        map.miss(9, 9);
        assertThat(map.get(9, 9)).isEqualTo(OccupancyMap.OCCUPIED);

        map.hit(1, 1);
        List<String> all = new ArrayList<>();
        map.forEachOccupied((i, j) -> all.add(i + "," + j));
        assertThat(all).containsExactlyInAnyOrder("1,1", "5,5", "9,9");
    }

    @Test
    void aSearchFindsAnOccupiedCellOnlyWhileItIsOccupiedWhereverItsChunkCameFrom() {
        OccupancyMap map = OccupancyMap.empty();
        int i = OccupancyMap.cell(-3.01);
        int j = OccupancyMap.cell(2.0);
        assertThat(map.occupiedWithin(-3.0, 2.0, 0.2)).isFalse();
        map.hit(i, j);
        assertThat(map.occupiedWithin(-3.0, 2.0, 0.2)).isTrue();
        assertThat(map.occupiedApproached(-3.5, 2.0, -3.0, 2.0, 0.2)).isTrue();
        long version = map.occupancyVersion();
        for (int pass = 0; pass < OccupancyMap.HIT / OccupancyMap.MISS; pass++) {
            map.miss(i, j); // rays passing through take the one hit's evidence away
        }
        assertThat(map.occupiedWithin(-3.0, 2.0, 0.2)).isFalse();
        assertThat(map.occupancyVersion()).isNotEqualTo(version);
        // the same chunk read back as a row replaces it; unchanged rows leave the version alone
        OccupancyMap writer = OccupancyMap.empty();
        writer.hit(i, j);
        List<MapChunk> rows = writer.takeChanged();
        map.putAll(rows);
        assertThat(map.occupiedWithin(-3.0, 2.0, 0.2)).isTrue();
        version = map.occupancyVersion();
        map.putAll(rows);
        assertThat(map.occupancyVersion()).as("the same occupied cells").isEqualTo(version);
        assertThat(map.occupiedWithin(-3.0, 2.0, 0.2)).isTrue();
    }

    @Test
    void theFlipsSinceAVersionAreToldWhileTheJournalHoldsThem() {
        OccupancyMap map = OccupancyMap.empty();
        map.set(1, 2, OccupancyMap.OCCUPIED);
        long v = map.occupancyVersion();
        map.set(3, 4, OccupancyMap.OCCUPIED);
        map.set(3, 5, OccupancyMap.FREE); // seen, not a flip
        map.set(1, 2, OccupancyMap.FREE);
        java.util.List<String> flips = new java.util.ArrayList<>();
        assertThat(map.forEachFlipSince(v, (i, j) -> flips.add(i + "," + j))).isTrue();
        assertThat(flips).containsExactly("3,4", "1,2");
        for (int k = 0; k < 5000; k++) {
            map.set(k, -7, OccupancyMap.OCCUPIED);
        }
        assertThat(map.forEachFlipSince(v, (i, j) -> { })).as("older than the journal").isFalse();
    }
}
