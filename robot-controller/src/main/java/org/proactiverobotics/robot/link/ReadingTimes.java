package org.proactiverobotics.robot.link;

/**
 * The simulated times (milliseconds) of the newest readings of one sensor that a link wrote, in
 * a ring: enough to name the k-th newest without reading the table back. Grows on demand up to
 * {@link #MAX_CAPACITY} times; thread-safe.
 */
final class ReadingTimes {

    /** The most times kept (1 MB): a retention that keeps more asks the table instead. */
    static final int MAX_CAPACITY = 1 << 17;
    private static final int INITIAL_CAPACITY = 2048;

    private long[] ring = new long[INITIAL_CAPACITY];
    /** How many times were added in all; the newest is at {@code (added - 1) % ring.length}. */
    private long added;

    /**
     * Records a reading's time. The newest time again is the same reading, ignored; an earlier
     * one is a new run (its clock back at 0): what was held is forgotten.
     *
     * @param simTimeMs the reading's simulated time, ms
     */
    synchronized void add(long simTimeMs) {
        if (added > 0) {
            long newest = ring[(int) ((added - 1) % ring.length)];
            if (simTimeMs == newest) {
                return;
            }
            if (simTimeMs < newest) {
                added = 0;
            }
        }
        ring[(int) (added % ring.length)] = simTimeMs;
        added++;
    }

    /**
     * @param k 1 for the newest, 2 for the one before, ...
     * @return the k-th newest time recorded, or -1 when fewer than k are held (the ring then
     *         makes room for k, up to {@link #MAX_CAPACITY}, for the next time it is asked)
     */
    synchronized long newest(int k) {
        if (k < 1) {
            throw new IllegalArgumentException("k must be >= 1: " + k);
        }
        if (k > ring.length) {
            grow(Math.min(k, MAX_CAPACITY));
            return -1;
        }
        if (k > added) {
            return -1;
        }
        return ring[(int) ((added - k) % ring.length)];
    }

    /** Keeps the times held, newest last, in a larger ring. */
    private void grow(int capacity) {
        if (capacity <= ring.length) {
            return;
        }
        int held = (int) Math.min(added, ring.length);
        long[] bigger = new long[capacity];
        for (int i = 0; i < held; i++) {
            bigger[i] = ring[(int) ((added - held + i) % ring.length)];
        }
        ring = bigger;
        added = held;
    }
}
