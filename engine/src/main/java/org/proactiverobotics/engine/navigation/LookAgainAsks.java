package org.proactiverobotics.engine.navigation;

import java.util.Map;

/**
 * A rule's asks to look again ({@link SharedWorld#LOOK_AGAIN}): once a condition (no route to the
 * checkpoint, held for the battery) has lasted {@value #AFTER_MS} ms, and as long after each ask, at
 * most {@value #LIMIT} times for the rule that holds it. Plain fields: saved with that rule.
 */
public final class LookAgainAsks {

    /** How long the condition lasts before an ask, and how far apart asks are, simulated ms. */
    public static final long AFTER_MS = 5_000;
    /** The most asks. */
    public static final int LIMIT = 3;

    private int asks;
    /** The simulated time of the last ask, ms (-1: none). */
    private long lastAskMs = -1;

    /**
     * Asks the mapping to look again when it is due.
     *
     * @param values  the shared memory's named values ({@code ctx.memory().values()})
     * @param sinceMs since when the condition has lasted, simulated ms
     * @param nowMs   now, simulated ms
     */
    public void askWhenDue(Map<String, String> values, long sinceMs, long nowMs) {
        if (asks >= LIMIT || nowMs - Math.max(sinceMs, lastAskMs) < AFTER_MS) {
            return;
        }
        asks++;
        lastAskMs = nowMs;
        SharedWorld.askToLookAgain(values);
    }
}
