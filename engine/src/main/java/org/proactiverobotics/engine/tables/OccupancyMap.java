package org.proactiverobotics.engine.tables;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * A sparse occupancy grid in chunks, as stored in {@code occupancy_map}: cells of
 * {@value #CELL_M} m, each unknown, free or occupied; a cell never seen is unknown. A seen cell
 * keeps its evidence in its byte (log-odds in whole steps): a ray ending on it adds
 * {@value #HIT}, a ray passing through it takes {@value #MISS} away until its evidence reaches
 * {@value #CONFIRMED} (two hits without a ray through it between them: a wall, for good), and it is occupied while any evidence is left
 * (stored byte {@value #OCCUPIED} and above; {@value #FREE}: seen, no evidence). A single noisy
 * reading that drew a wall across a doorway is taken away again by the rays that later pass
 * through it; a wall seen twice, or once from close by ({@link #confirm}), stays. Remembers which chunks changed
 * since they were last taken ({@link #takeChanged()}). Not thread-safe.
 */
public final class OccupancyMap {

    /** A cell's side, metres. */
    public static final double CELL_M = 0.05;
    /** Cells along a chunk's side. */
    public static final int CHUNK_CELLS = 16;
    // floorDiv and floorMod by CHUNK_CELLS (a power of two), negative indices included
    private static final int CHUNK_SHIFT = 4;
    private static final int CHUNK_MASK = CHUNK_CELLS - 1;
    /** Never seen. */
    public static final byte UNKNOWN = 0;
    /** A ray crossed it. */
    public static final byte FREE = 1;
    /** A ray ended on it (and its evidence is not used up). */
    public static final byte OCCUPIED = 2;
    /** Evidence a ray ending on a cell adds. */
    public static final int HIT = 3;
    /** Evidence a ray passing through a cell takes away. */
    public static final int MISS = 1;
    /** Evidence from which a cell is a wall for good: passing rays no longer take it away (two hits). */
    public static final int CONFIRMED = 2 * HIT;

    // Chunks in a dense row-major array over a rectangle of chunk indices that grows as the map
    // does: a lookup is an index, not a hash (Long keys hash to cx ^ cy, which collides along diagonals).
    private byte[][] chunks = new byte[0][];
    /** Each chunk's occupied cells, indexed as {@link #chunks}: a search skips the chunks with none. */
    private int[] occupiedIn = new int[0];
    /**
     * How many chunks holding an occupied cell each block of {@value #BLOCK_CHUNKS} × {@value #BLOCK_CHUNKS}
     * chunks of the array holds (block (a, b) covers the array's chunk columns 8a to 8a + 7, rows
     * likewise): a look along tens of metres of line passes an empty stretch at once.
     */
    private int[] blockOccupied = new int[0];
    private int blockColumns;
    /** Chunks along a block's side (6.4 m). */
    public static final int BLOCK_CHUNKS = 8;
    private static final int BLOCK_SHIFT = 3;
    /** The most chunks the array may span: a square of about 3 km on a side (128 MB of references at most). */
    private static final long MAX_CHUNKS = 1L << 24;
    private int originCx;
    private int originCy;
    private int columns;
    private int rows;
    private int stored;
    /** Counts changes to which cells are occupied: equal counts, the same occupied cells. */
    private long occupancyVersion;
    /** The cells whose occupancy flipped, packed ({@link #key}), flip v at index v mod the length: the newest {@value #JOURNAL} flips. */
    private final long[] journal = new long[JOURNAL];
    /** How many flips the journal keeps. */
    private static final int JOURNAL = 4096;
    private final Set<Long> changed = new LinkedHashSet<>();
    private int minCx = Integer.MAX_VALUE;
    private int minCy = Integer.MAX_VALUE;
    private int maxCx = Integer.MIN_VALUE;
    private int maxCy = Integer.MIN_VALUE;

    /** @return an empty map */
    public static OccupancyMap empty() {
        return new OccupancyMap();
    }

    /**
     * @param rows the stored chunks
     * @return the map they hold, nothing marked changed
     */
    public static OccupancyMap of(List<MapChunk> rows) {
        OccupancyMap map = new OccupancyMap();
        map.putAll(rows);
        return map;
    }

    static long key(int cx, int cy) {
        return ((long) cx << 32) | (cy & 0xffffffffL);
    }

    /** @return the chunk at chunk indices (cx, cy), or null when none is stored */
    private byte[] chunk(int cx, int cy) {
        int a = cx - originCx;
        int b = cy - originCy;
        return a < 0 || b < 0 || a >= columns || b >= rows ? null : chunks[b * columns + a];
    }

    /** Stores a chunk at chunk indices (cx, cy), growing the array (with room to spare) when it lies outside. */
    private void put(int cx, int cy, byte[] cells) {
        if (cx < originCx || cy < originCy || cx >= originCx + columns || cy >= originCy + rows) {
            boolean none = columns == 0;
            int loX = none ? cx : originCx;
            int loY = none ? cy : originCy;
            int hiX = none ? cx : originCx + columns - 1;
            int hiY = none ? cy : originCy + rows - 1;
            // only the axis that ran out grows, by half its extent (at least 4 chunks): amortised copies
            int spareX = Math.max(4, (hiX - loX + 1) / 2);
            int spareY = Math.max(4, (hiY - loY + 1) / 2);
            if (none || cx < loX) {
                loX = Math.min(loX, cx) - spareX;
            }
            if (none || cx > hiX) {
                hiX = Math.max(hiX, cx) + spareX;
            }
            if (none || cy < loY) {
                loY = Math.min(loY, cy) - spareY;
            }
            if (none || cy > hiY) {
                hiY = Math.max(hiY, cy) + spareY;
            }
            int w = hiX - loX + 1;
            long size = (long) w * (hiY - loY + 1);
            if (size > MAX_CHUNKS) {
                throw new IllegalStateException("the occupancy map would span " + size + " chunks of "
                        + CHUNK_CELLS * CELL_M + " m (more than " + MAX_CHUNKS + "): chunk (" + cx + ", " + cy + ") is too far away");
            }
            byte[][] grown = new byte[(int) size][];
            int[] grownCounts = new int[(int) size];
            for (int b = 0; b < rows; b++) {
                System.arraycopy(chunks, b * columns, grown, (originCy + b - loY) * w + originCx - loX, columns);
                System.arraycopy(occupiedIn, b * columns, grownCounts, (originCy + b - loY) * w + originCx - loX, columns);
            }
            chunks = grown;
            occupiedIn = grownCounts;
            originCx = loX;
            originCy = loY;
            columns = w;
            rows = hiY - loY + 1;
            countBlocks();
        }
        int at = (cy - originCy) * columns + cx - originCx;
        byte[] before = chunks[at];
        if (before == null) {
            stored++;
        }
        chunks[at] = cells;
        int occupied = 0;
        for (int q = 0; q < cells.length; q++) {
            boolean now = cells[q] >= OCCUPIED;
            if (now) {
                occupied++;
            }
            if (now != (before != null && before[q] >= OCCUPIED)) {
                // the map's rows are read again every iteration, mostly unchanged: only flips count
                occupancyVersion++;
                journal[(int) (occupancyVersion % JOURNAL)] = key(cx * CHUNK_CELLS + q % CHUNK_CELLS, cy * CHUNK_CELLS + q / CHUNK_CELLS);
            }
        }
        countChunk(at, occupiedIn[at], occupied);
        occupiedIn[at] = occupied;
        extend(cx, cy);
    }

    /** The blocks' counts worked out afresh over the array (after it grew: its origin moved). */
    private void countBlocks() {
        blockColumns = (columns + BLOCK_CHUNKS - 1) >> BLOCK_SHIFT;
        blockOccupied = new int[blockColumns * ((rows + BLOCK_CHUNKS - 1) >> BLOCK_SHIFT)];
        for (int at = 0; at < occupiedIn.length; at++) {
            countChunk(at, 0, occupiedIn[at]);
        }
    }

    /** Counts a chunk (index in the array) into its block when it came to hold, or stopped holding, an occupied cell. */
    private void countChunk(int at, int before, int after) {
        if ((before > 0) != (after > 0)) {
            blockOccupied[((at / columns) >> BLOCK_SHIFT) * blockColumns + ((at % columns) >> BLOCK_SHIFT)] += after > 0 ? 1 : -1;
        }
    }

    /** @return the cell index (column) holding an x, or row holding a y, metres */
    public static int cell(double m) {
        return (int) Math.floor(m / CELL_M);
    }

    /** @return the centre of a cell column or row, metres */
    public static double centre(int cell) {
        return (cell + 0.5) * CELL_M;
    }

    /** Told of a cell, by its grid indices. */
    @FunctionalInterface
    public interface CellVisitor {
        /**
         * @param i the cell's column index
         * @param j the cell's row index
         */
        void cell(int i, int j);
    }

    /**
     * Visits every occupied cell, chunk by chunk: what a planner needs, at the cost of the known
     * chunks rather than one lookup per cell of its grid.
     *
     * @param visitor told of each occupied cell
     */
    public void forEachOccupied(CellVisitor visitor) {
        for (int b = 0; b < rows; b++) {
            for (int a = 0; a < columns; a++) {
                byte[] c = chunks[b * columns + a];
                if (c == null) {
                    continue;
                }
                int cx = originCx + a;
                int cy = originCy + b;
                for (int q = 0; q < c.length; q++) {
                    if (c[q] >= OCCUPIED) {
                        visitor.cell(cx * CHUNK_CELLS + q % CHUNK_CELLS, cy * CHUNK_CELLS + q / CHUNK_CELLS);
                    }
                }
            }
        }
    }

    /** @return the state of a cell (column i, row j) */
    public byte get(int i, int j) {
        byte[] c = chunk(i >> CHUNK_SHIFT, j >> CHUNK_SHIFT);
        if (c == null) {
            return UNKNOWN;
        }
        byte raw = c[(j & CHUNK_MASK) * CHUNK_CELLS + (i & CHUNK_MASK)];
        return raw >= OCCUPIED ? OCCUPIED : raw;
    }

    /** @return a cell's evidence of being occupied (0 for free or unknown) */
    public int evidence(int i, int j) {
        byte[] c = chunk(i >> CHUNK_SHIFT, j >> CHUNK_SHIFT);
        return c == null ? 0 : Math.max(0, c[(j & CHUNK_MASK) * CHUNK_CELLS + (i & CHUNK_MASK)] - FREE);
    }

    /**
     * A ray ended on a cell: adds {@value #HIT} to its evidence.
     *
     * @return whether the cell's byte changed
     */
    public boolean hit(int i, int j) {
        int e = Math.min(CONFIRMED, evidence(i, j) + HIT);
        return setRaw(i, j, (byte) (FREE + e));
    }

    /**
     * A ray ended on a cell from close by, where readings do not stray: a wall for good.
     *
     * @return whether the cell's byte changed
     */
    public boolean confirm(int i, int j) {
        return setRaw(i, j, (byte) (FREE + CONFIRMED));
    }

    /**
     * A ray passed through a cell: it is seen, and loses {@value #MISS} of its evidence unless it is
     * a confirmed wall.
     *
     * @return whether the cell's byte changed
     */
    public boolean miss(int i, int j) {
        int e = evidence(i, j);
        if (e >= CONFIRMED) {
            return false;
        }
        e = Math.max(0, e - MISS);
        return setRaw(i, j, (byte) (FREE + e));
    }

    /**
     * A ray passed well through a cell, in a world where obstacles move: it loses {@value #MISS} of
     * its evidence even when it was a wall for good (a robot that stood there and left). Only for
     * rays that went on well beyond the cell: a ray ending in a wall's cell is no proof it is empty.
     *
     * @return whether the cell's byte changed
     */
    public boolean clear(int i, int j) {
        return setRaw(i, j, (byte) (FREE + Math.max(0, evidence(i, j) - MISS)));
    }

    /**
     * Sets a cell's state ({@link #OCCUPIED}: the evidence of one hit short of a wall seen once,
     * i.e. the least evidence); its chunk is marked changed when the byte changes.
     *
     * @return whether the state changed
     */
    public boolean set(int i, int j, byte state) {
        return setRaw(i, j, state);
    }

    private boolean setRaw(int i, int j, byte state) {
        int cx = Math.floorDiv(i, CHUNK_CELLS);
        int cy = Math.floorDiv(j, CHUNK_CELLS);
        long k = key(cx, cy);
        byte[] c = chunk(cx, cy);
        if (c == null) {
            if (state == UNKNOWN) {
                return false;
            }
            c = new byte[CHUNK_CELLS * CHUNK_CELLS];
            put(cx, cy, c);
        }
        int at = Math.floorMod(j, CHUNK_CELLS) * CHUNK_CELLS + Math.floorMod(i, CHUNK_CELLS);
        if (c[at] == state) {
            return false;
        }
        if ((c[at] >= OCCUPIED) != (state >= OCCUPIED)) {
            int slot = (cy - originCy) * columns + cx - originCx;
            countChunk(slot, occupiedIn[slot], occupiedIn[slot] + (state >= OCCUPIED ? 1 : -1));
            occupiedIn[slot] += state >= OCCUPIED ? 1 : -1;
            occupancyVersion++;
            journal[(int) (occupancyVersion % JOURNAL)] = key(i, j);
        }
        c[at] = state;
        changed.add(k);
        return true;
    }

    private void extend(int cx, int cy) {
        minCx = Math.min(minCx, cx);
        minCy = Math.min(minCy, cy);
        maxCx = Math.max(maxCx, cx);
        maxCy = Math.max(maxCy, cy);
    }

    /** @return a count that changes whenever a cell becomes or stops being occupied (a cache's key) */
    public long occupancyVersion() {
        return occupancyVersion;
    }

    /**
     * Visits the cells whose occupancy flipped since a version (a cell may come more than once),
     * when the map still knows them: an incremental consumer's way to update what it derived.
     *
     * @param version an earlier {@link #occupancyVersion()}
     * @param visitor told of each flipped cell
     * @return false (nothing visited) when the map no longer knows which cells flipped since then
     */
    public boolean forEachFlipSince(long version, CellVisitor visitor) {
        if (occupancyVersion - version > JOURNAL || version > occupancyVersion) {
            return false;
        }
        for (long v = version + 1; v <= occupancyVersion; v++) {
            long k = journal[(int) (v % JOURNAL)];
            visitor.cell((int) (k >> 32), (int) k);
        }
        return true;
    }

    /** @return whether no chunk is stored */
    public boolean isEmpty() {
        return stored == 0;
    }

    /** @return the lowest column of a stored chunk's cells (undefined when empty) */
    public int minCell(boolean x) {
        return (x ? minCx : minCy) * CHUNK_CELLS;
    }

    /** @return one past the highest column (x) or row (y) of a stored chunk's cells (undefined when empty) */
    public int maxCellExclusive(boolean x) {
        return ((x ? maxCx : maxCy) + 1) * CHUNK_CELLS;
    }

    /** @return the chunks changed since they were last taken, each once, and forgets them */
    public List<MapChunk> takeChanged() {
        List<MapChunk> out = new ArrayList<>(changed.size());
        for (long k : changed) {
            out.add(new MapChunk((int) (k >> 32), (int) k, chunk((int) (k >> 32), (int) k).clone()));
        }
        changed.clear();
        return out;
    }

    /**
     * A quick test before many {@link #occupiedWithin} or {@link #occupiedApproached} calls in one
     * box: false means none of them can find an occupied cell there.
     *
     * @param minXM the box's least x, metres
     * @param minYM its least y, metres
     * @param maxXM its greatest x, metres
     * @param maxYM its greatest y, metres
     * @return whether a chunk overlapping the cells the box touches holds an occupied cell
     */
    public boolean occupiedChunkIn(double minXM, double minYM, double maxXM, double maxYM) {
        return anyOccupied(cell(minXM), cell(minYM), cell(maxXM), cell(maxYM));
    }

    /**
     * As {@link #occupiedChunkIn}, by blocks of {@value #BLOCK_CHUNKS} × {@value #BLOCK_CHUNKS} chunks:
     * coarser (true more often), at the cost of a look or four for a box of a few metres.
     *
     * @param minXM the box's least x, metres
     * @param minYM its least y, metres
     * @param maxXM its greatest x, metres
     * @param maxYM its greatest y, metres
     * @return whether a block overlapping the cells the box touches holds an occupied cell
     */
    public boolean occupiedBlockIn(double minXM, double minYM, double maxXM, double maxYM) {
        int a0 = Math.max(0, (cell(minXM) >> CHUNK_SHIFT) - originCx) >> BLOCK_SHIFT;
        int a1 = Math.min(columns - 1, (cell(maxXM) >> CHUNK_SHIFT) - originCx) >> BLOCK_SHIFT;
        int b0 = Math.max(0, (cell(minYM) >> CHUNK_SHIFT) - originCy) >> BLOCK_SHIFT;
        int b1 = Math.min(rows - 1, (cell(maxYM) >> CHUNK_SHIFT) - originCy) >> BLOCK_SHIFT;
        for (int b = b0; b <= b1; b++) {
            for (int a = a0; a <= a1; a++) {
                if (blockOccupied[b * blockColumns + a] > 0) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * @param xM      a point's x, metres
     * @param yM      its y, metres
     * @param radiusM a distance, metres
     * @return whether an occupied cell's centre lies within that distance of the point
     */
    public boolean occupiedWithin(double xM, double yM, double radiusM) {
        int i0 = cell(xM - radiusM);
        int i1 = cell(xM + radiusM);
        int j0 = cell(yM - radiusM);
        int j1 = cell(yM + radiusM);
        if (!anyOccupied(i0, j0, i1, j1)) {
            return false;
        }
        double r2 = radiusM * radiusM;
        for (int j = j0; j <= j1; j++) {
            double dy = centre(j) - yM;
            for (int i = i0; i <= i1; i++) {
                double dx = centre(i) - xM;
                if (dx * dx + dy * dy <= r2 && get(i, j) == OCCUPIED) {
                    return true;
                }
            }
        }
        return false;
    }

    /** @return whether a chunk overlapping the cells i0..i1 × j0..j1 (inclusive) holds an occupied cell */
    private boolean anyOccupied(int i0, int j0, int i1, int j1) {
        int a0 = Math.max(0, (i0 >> CHUNK_SHIFT) - originCx);
        int a1 = Math.min(columns - 1, (i1 >> CHUNK_SHIFT) - originCx);
        int b0 = Math.max(0, (j0 >> CHUNK_SHIFT) - originCy);
        int b1 = Math.min(rows - 1, (j1 >> CHUNK_SHIFT) - originCy);
        for (int b = b0; b <= b1; b++) {
            for (int a = a0; a <= a1; a++) {
                if (occupiedIn[b * columns + a] > 0) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Whether moving to a point would bring the body closer to an occupied cell than it may come:
     * {@link #approached} for occupied cells, chunk by chunk. A chunk with none is passed, and in the
     * others a cell's byte is read before its distances are worked out (6 % of a floor's mission, JFR).
     *
     * @param fromX where the body is now, x, metres
     * @param fromY its y, metres
     * @param px    the point, x, metres
     * @param py    its y, metres
     * @param keepM how close the body's centre may come to an occupied cell's centre, metres
     * @return whether an occupied cell's centre lies within {@code keepM} of the point and closer to it than to where the body is
     */
    public boolean occupiedApproached(double fromX, double fromY, double px, double py, double keepM) {
        int i0 = cell(px - keepM);
        int i1 = cell(px + keepM);
        int j0 = cell(py - keepM);
        int j1 = cell(py + keepM);
        double keep2 = keepM * keepM;
        for (int cy = j0 >> CHUNK_SHIFT; cy <= j1 >> CHUNK_SHIFT; cy++) {
            for (int cx = i0 >> CHUNK_SHIFT; cx <= i1 >> CHUNK_SHIFT; cx++) {
                int a = cx - originCx;
                int b = cy - originCy;
                if (a < 0 || b < 0 || a >= columns || b >= rows || occupiedIn[b * columns + a] == 0) {
                    continue;
                }
                byte[] c = chunks[b * columns + a];
                int ja = Math.max(j0, cy << CHUNK_SHIFT);
                int jb = Math.min(j1, (cy << CHUNK_SHIFT) + CHUNK_MASK);
                int ia = Math.max(i0, cx << CHUNK_SHIFT);
                int ib = Math.min(i1, (cx << CHUNK_SHIFT) + CHUNK_MASK);
                for (int j = ja; j <= jb; j++) {
                    int row = (j & CHUNK_MASK) * CHUNK_CELLS;
                    for (int i = ia; i <= ib; i++) {
                        if (c[row + (i & CHUNK_MASK)] >= OCCUPIED) {
                            double ccx = centre(i);
                            double ccy = centre(j);
                            double d2 = (ccx - px) * (ccx - px) + (ccy - py) * (ccy - py);
                            if (d2 < keep2 && d2 < (ccx - fromX) * (ccx - fromX) + (ccy - fromY) * (ccy - fromY) - 1e-6) {
                                return true;
                            }
                        }
                    }
                }
            }
        }
        return false;
    }

    /**
     * As {@link #occupiedApproached} for the cells the rays never saw.
     *
     * @return whether a never-seen cell's centre lies within {@code keepM} of the point and closer to it than to where the body is
     */
    public boolean unknownApproached(double fromX, double fromY, double px, double py, double keepM) {
        return approached(fromX, fromY, px, py, keepM, UNKNOWN);
    }

    /** Whether a cell in this state lies within {@code keepM} of the point and closer to it than to where the body is. */
    private boolean approached(double fromX, double fromY, double px, double py, double keepM, byte state) {
        int i0 = cell(px - keepM);
        int i1 = cell(px + keepM);
        int j0 = cell(py - keepM);
        int j1 = cell(py + keepM);
        double keep2 = keepM * keepM;
        for (int j = j0; j <= j1; j++) {
            double cy = centre(j);
            for (int i = i0; i <= i1; i++) {
                double cx = centre(i);
                double d2 = (cx - px) * (cx - px) + (cy - py) * (cy - py);
                if (d2 < keep2 && d2 < (cx - fromX) * (cx - fromX) + (cy - fromY) * (cy - fromY) - 1e-6
                        && get(i, j) == state) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Merges stored chunks into the map, replacing those at the same place (nothing marked changed).
     *
     * @param rows the chunks read
     */
    public void putAll(List<MapChunk> rows) {
        for (MapChunk c : rows) {
            put(c.chunkX(), c.chunkY(), c.cells().clone());
        }
    }

    /** @return how many cells are occupied */
    public int occupiedCells() {
        int n = 0;
        for (byte[] c : chunks) {
            if (c == null) {
                continue;
            }
            for (byte b : c) {
                if (b >= OCCUPIED) {
                    n++;
                }
            }
        }
        return n;
    }
}
