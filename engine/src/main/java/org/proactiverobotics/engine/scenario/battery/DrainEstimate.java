package org.proactiverobotics.engine.scenario.battery;

/**
 * How much battery a metre of travel costs, learnt from what the engine sees: GPS positions and
 * battery readings, while not charging. Until enough has been travelled it assumes a cautious
 * prior. Also how much longer than the straight line the way to the station has turned out to be
 * (the detour factor of the trips made so far, never below {@link #MIN_DETOUR}). Plain fields, so
 * it is saved with the rule that holds it.
 */
final class DrainEstimate {

    /** Assumed cost before anything is learnt, percent per metre (cautious: twice a world's default). */
    static final double PRIOR_PCT_PER_M = 2.0;
    /** Travel needed before the measurement replaces the prior, metres. */
    static final double LEARN_AFTER_M = 1.0;

    /** The detour assumed for a way not yet driven: paths round obstacles are longer than straight lines. */
    static final double MIN_DETOUR = 1.4;
    /** A trip this much longer than its straight line was a robot lost on the way, not a measure of the world. */
    static final double MAX_DETOUR = 3.0;
    /** Trips shorter than this, in straight line, teach nothing about detours, metres. */
    static final double DETOUR_LEARN_AFTER_M = 1.0;

    private double travelledM;
    private double detour = MIN_DETOUR;
    private double drainedPct;
    private double sinceReadingM;
    private boolean hasLast;
    private double lastX;
    private double lastY;
    private double lastLevelPct;
    private long lastBatteryMs = -1;
    private transient double lastStepM;

    /** Adds a GPS position: the distance from the previous one counts as travel. */
    void position(double x, double y) {
        lastStepM = hasLast ? Math.hypot(x - lastX, y - lastY) : 0.0;
        sinceReadingM += lastStepM;
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

    /**
     * Learns from a finished trip to the station.
     *
     * @param drivenM   the distance driven on the trip, metres
     * @param straightM the straight-line distance from where it started, metres
     */
    void trip(double drivenM, double straightM) {
        if (straightM >= DETOUR_LEARN_AFTER_M) {
            detour = Math.max(detour, Math.min(MAX_DETOUR, drivenM / straightM));
        }
    }

    /** @return how much longer than the straight line a way is assumed to be: at least {@value #MIN_DETOUR} */
    double detour() {
        return detour;
    }

    /** @return the distance since the previous GPS position, metres (0 for the first) */
    double lastStepM() {
        return lastStepM;
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
