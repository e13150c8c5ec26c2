package org.proactiverobotics.engine.scenario.battery;

/**
 * How much battery a metre of travel costs, learnt from what the engine sees: GPS positions and
 * battery readings, while not charging. Until enough has been travelled it assumes a cautious
 * prior. Also how much longer than the way planned on the map the way driven to the station has
 * turned out to be (the detour factor of the trips made so far, never below {@link #MIN_DETOUR}). Plain fields, so
 * it is saved with the rule that holds it.
 */
final class DrainEstimate {

    /** Assumed cost before anything is learnt, percent per metre (cautious: twice a world's default). */
    static final double PRIOR_PCT_PER_M = 2.0;
    /** Travel is counted in strides of at least this, metres. */
    static final double STRIDE_M = 0.25;
    /** Travel needed before the measurement replaces the prior, metres. */
    static final double LEARN_AFTER_M = 1.0;

    /**
     * The detour assumed for a way not yet driven: the route may cross cells no ray has seen (when the
     * seen ones hold none, it is planned with unknown cells free), and walls found on the way lengthen it.
     */
    static final double MIN_DETOUR = 1.25;
    /** A trip this much longer than its planned way was a robot lost on the way, not a measure of the world. */
    static final double MAX_DETOUR = 3.0;
    /** Trips planned shorter than this teach nothing about detours, metres. */
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

    /**
     * Adds a GPS position: travel counts in strides of at least {@value #STRIDE_M} m from the last
     * counted position (summed step by step, a GPS's noise of a few centimetres on 1.6 cm steps would
     * count several times the distance driven, and the cost per metre would come out far too low).
     */
    void position(double x, double y) {
        lastStepM = 0.0;
        if (!hasLast) {
            hasLast = true;
            lastX = x;
            lastY = y;
            return;
        }
        double stride = Math.hypot(x - lastX, y - lastY);
        if (stride >= STRIDE_M) {
            lastStepM = stride;
            sinceReadingM += stride;
            lastX = x;
            lastY = y;
        }
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
     * @param drivenM  the distance driven on the trip, metres
     * @param plannedM the length of the way planned when it started, metres
     */
    void trip(double drivenM, double plannedM) {
        if (plannedM >= DETOUR_LEARN_AFTER_M) {
            detour = Math.max(detour, Math.min(MAX_DETOUR, drivenM / plannedM));
        }
    }

    /** @return how much longer than the planned way a way is assumed to be: at least {@value #MIN_DETOUR} */
    double detour() {
        return detour;
    }

    /** @return the stride the last position completed, metres (0 when it completed none) */
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
