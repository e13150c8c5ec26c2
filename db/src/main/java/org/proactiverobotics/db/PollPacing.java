package org.proactiverobotics.db;

/**
 * Paces one side of the synchronous handshake while it polls for the other side (the robot for
 * the engine's iteration, the engine for the robot's next step). MySQL and MariaDB cannot notify
 * a waiting client, so the wait is a poll; but the other side's turn takes about as long as its
 * last turns did, so the first poll comes after most of that expected time and the next ones
 * close together. A step then costs a few polls instead of dozens, and the polls no longer take
 * the processor from the work they wait for (on two cores, they did).
 *
 * <p>The expected wait is the shortest of the last few waits that ended while the other side was
 * quick (a slow turn, a garbage collection, does not make the next polls late); a long wait (the
 * other side away) does not count, and the pauses then grow to spare the server. Not
 * thread-safe: one per waiting loop.
 */
public final class PollPacing {

    /** Waits longer than this are the other side being away, not its turn: they are not averaged. */
    static final long QUICK_NANOS = 50_000_000L;
    /** The closest polls, ns. */
    static final long MIN_PAUSE_NANOS = 20_000L;
    /** Share of the expected wait slept through before the first poll. */
    private static final double FIRST_SHARE = 0.5;
    /** Polls after the first one: this many per expected wait. */
    private static final int POLLS_PER_WAIT = 16;
    /** How many of the last waits the expectation looks at. */
    private static final int RECENT = 8;

    /** The last quick waits, ns: the shortest is what the other side's turn surely takes. */
    private final long[] recent = new long[RECENT];
    private int recorded;

    /**
     * @param waitedNanos how long this wait has lasted so far, ns
     * @param polls       how many polls this wait has made so far (0 before the first)
     * @return how long to pause before the next poll, ns
     */
    public long pauseNanos(long waitedNanos, int polls) {
        if (waitedNanos >= QUICK_NANOS) { // the other side is away: spare the server
            return waitedNanos < 1_000_000_000L ? 1_000_000L : waitedNanos < 10_000_000_000L ? 10_000_000L : 50_000_000L;
        }
        long expected = expectedNanos();
        if (polls == 0) {
            return Math.max(MIN_PAUSE_NANOS, (long) (expected * FIRST_SHARE) - waitedNanos);
        }
        return Math.max(MIN_PAUSE_NANOS, expected / POLLS_PER_WAIT);
    }

    /**
     * Records a wait that ended (the other side answered).
     *
     * @param waitedNanos how long it lasted, ns
     */
    public void waited(long waitedNanos) {
        if (waitedNanos < 0 || waitedNanos >= QUICK_NANOS) {
            return;
        }
        recent[recorded++ % RECENT] = waitedNanos;
    }

    /** @return the shortest of the last quick waits, ns (0 before any) */
    public long expectedNanos() {
        int n = Math.min(recorded, RECENT);
        long shortest = n == 0 ? 0 : Long.MAX_VALUE;
        for (int k = 0; k < n; k++) {
            shortest = Math.min(shortest, recent[k]);
        }
        return shortest;
    }
}
