package org.proactiverobotics.engine.scenario.battery;

/**
 * How much battery a metre of travel costs, learnt from what the engine sees: GPS positions and
 * battery readings, while not charging. Until enough has been travelled it assumes a cautious
 * prior. Plain fields, so it is saved with the rule that holds it.
 */
final class DrainEstimate {

    /** Assumed cost before anything is learnt, percent per metre (cautious: twice a world's default). */
    static final double PRIOR_PCT_PER_M = 2.0;
    /** Travel needed before the measurement replaces the prior, metres. */
    static final double LEARN_AFTER_M = 1.0;

    private double travelledM;
    private double drainedPct;
    private double sinceReadingM;
    private boolean hasLast;
    private double lastX;
    private double lastY;
    private double lastLevelPct;
    private long lastBatteryMs = -1;

    /** Adds a GPS position: the distance from the previous one counts as travel. */
    void position(double x, double y) {
        if (hasLast) {
            sinceReadingM += Math.hypot(x - lastX, y - lastY);
        }
        hasLast = true;
        lastX = x;
        lastY = y;
    }

    /** Adds a battery reading; a new one closes the stretch travelled since the last. */
    void battery(long simTimeMs, double levelPct, boolean charging) {
        if (simTimeMs == lastBatteryMs) {
            return;
        }
        if (lastBatteryMs >= 0 && !charging && levelPct <= lastLevelPct) {
            travelledM += sinceReadingM;
            drainedPct += lastLevelPct - levelPct;
        }
        sinceReadingM = 0;
        lastBatteryMs = simTimeMs;
        lastLevelPct = levelPct;
    }

    /** @return whether enough travel has been seen to replace the prior by a measurement */
    boolean learnt() {
        return travelledM >= LEARN_AFTER_M;
    }

    /** @return the estimated cost of travel, percent per metre */
    double pctPerMetre() {
        return travelledM < LEARN_AFTER_M ? PRIOR_PCT_PER_M : drainedPct / travelledM;
    }
}
