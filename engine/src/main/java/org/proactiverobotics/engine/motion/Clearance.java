package org.proactiverobotics.engine.motion;

/**
 * How close the robot may come to an obstacle ahead, derived from what the engine knows of it:
 * its top speed (the {@link DriveProfile}), the control period (measured from the readings'
 * clock) and the sensors' range. Metres from the robot's rim, as the distance sensors read.
 *
 * <p>The braking reach is the distance covered at top speed during three control periods (a
 * reading is answered, decided and acted on one period apart each) plus 0.2 s to turn away: at
 * the world defaults (0.5 m/s, 32 ms) 0.15 m; a faster robot or a slower clock looks further
 * ahead, a slow one comes closer. The collision monitor scales it by the command's speed.
 *
 * @param imminentM the braking reach at top speed: closer than this ahead, stop and turn on the spot
 */
public record Clearance(double imminentM) {

    /** The control period assumed until one is measured, milliseconds (the world files' default). */
    public static final long DEFAULT_PERIOD_MS = 32;
    /** The sensor range assumed when none is known, metres (the world files' default). */
    public static final double DEFAULT_RANGE_M = 1.0;
    /** Periods between a reading and the wheels obeying the command decided from it. */
    private static final int REACTION_PERIODS = 3;
    /** Time to turn away from an obstacle once the command arrives, seconds. */
    private static final double TURN_AWAY_S = 0.2;

    /** The reach at the world defaults. */
    public static final Clearance DEFAULT = of(DriveProfile.DEFAULT, DEFAULT_PERIOD_MS, DEFAULT_RANGE_M);

    /**
     * @param profile  the robot's top speed and axle width
     * @param periodMs the control period, milliseconds (the time between two readings)
     * @param rangeM   the distance sensors' range, metres
     * @return the reach for that robot: at least 5 cm, never beyond 90 % of the range (what a free ray reads)
     */
    public static Clearance of(DriveProfile profile, long periodMs, double rangeM) {
        double speedTermM = profile.maxSpeedMps() * (REACTION_PERIODS * periodMs / 1000.0 + TURN_AWAY_S);
        return new Clearance(Math.min(0.9 * rangeM, Math.max(0.05, speedTermM + 0.002)));
    }
}
