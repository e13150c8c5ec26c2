package org.proactiverobotics.robot;

/**
 * Expires when no new command has been fed for longer than a time-out, measured in simulated
 * time (so that lockstep runs are deterministic). Not armed until the first feed: a robot that
 * never got a command is waiting, not abandoned.
 */
public final class Watchdog {

    private final long timeoutMs;
    private long lastFedMs = Long.MIN_VALUE;

    /** @param timeoutMs the longest gap between new commands, simulated milliseconds (> 0) */
    public Watchdog(long timeoutMs) {
        if (timeoutMs <= 0) {
            throw new IllegalArgumentException("watchdog time-out must be > 0 ms: " + timeoutMs);
        }
        this.timeoutMs = timeoutMs;
    }

    /** @param simTimeMs the simulated time a new command arrived, ms */
    public void feed(long simTimeMs) {
        lastFedMs = simTimeMs;
    }

    /** @return whether a command was ever fed */
    public boolean armed() {
        return lastFedMs != Long.MIN_VALUE;
    }

    /**
     * @param simTimeMs the simulated time now, ms
     * @return whether it is armed and the last feed is more than the time-out ago
     */
    public boolean expired(long simTimeMs) {
        return armed() && simTimeMs - lastFedMs > timeoutMs;
    }

    /** @return simulated ms since the last feed, or -1 when never fed */
    public long sinceLastFeedMs(long simTimeMs) {
        return armed() ? simTimeMs - lastFedMs : -1;
    }

    /** @return the time-out, simulated ms */
    public long timeoutMs() {
        return timeoutMs;
    }
}
