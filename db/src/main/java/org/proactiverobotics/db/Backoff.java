package org.proactiverobotics.db;

import java.util.function.LongSupplier;

/**
 * Exponential back-off between database attempts, in wall-clock time (it spares a real server,
 * not simulated time): after a failure, no attempt until the delay elapses; the delay doubles
 * with each further failure up to a ceiling and resets on success. The one back-off of both
 * sides: the robot's calls, its lockstep wait, the engine's loop and each robot it serves.
 */
public final class Backoff {

    private final long initialNanos;
    private final long maxNanos;
    private final LongSupplier nanoClock;
    private long delayNanos;
    private long nextAttemptNanos;
    private boolean failing;

    /**
     * @param initialMs the first delay, ms (>= 0)
     * @param maxMs     the longest delay, ms (>= initialMs)
     * @param nanoClock a monotonic clock in nanoseconds ({@code System::nanoTime})
     */
    public Backoff(long initialMs, long maxMs, LongSupplier nanoClock) {
        if (initialMs < 0 || maxMs < initialMs) {
            throw new IllegalArgumentException("back-off needs 0 <= initialMs <= maxMs: " + initialMs + ", " + maxMs);
        }
        this.initialNanos = initialMs * 1_000_000L;
        this.maxNanos = maxMs * 1_000_000L;
        this.nanoClock = nanoClock;
    }

    /** @return whether an attempt may be made now */
    public boolean ready() {
        return !failing || nanoClock.getAsLong() - nextAttemptNanos >= 0;
    }

    /** @return whether the last attempt failed */
    public boolean failing() {
        return failing;
    }

    /** Records a failed attempt and pushes the next one back. */
    public void failed() {
        delayNanos = failing ? Math.min(maxNanos, Math.max(delayNanos * 2, 1_000_000L)) : initialNanos;
        failing = true;
        nextAttemptNanos = nanoClock.getAsLong() + delayNanos;
    }

    /** Records a successful attempt: the next failure starts again from the first delay. */
    public void succeeded() {
        failing = false;
        delayNanos = 0;
    }

    /** @return the current delay, ms (0 when not failing) */
    public long delayMs() {
        return delayNanos / 1_000_000L;
    }
}
