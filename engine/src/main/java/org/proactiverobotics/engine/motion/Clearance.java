package org.proactiverobotics.engine.motion;

/**
 * How close the robot may come to an obstacle, derived from what the engine knows of it: its top
 * speed and body (the {@link DriveProfile}: the body is a disc whose wheels are on the rim, so its
 * radius is half the axle width), the control period (measured from the readings' clock) and the
 * sensors' range. All distances are metres from the robot's rim, as the distance sensors read.
 *
 * <p>The speed term is the distance covered at top speed during three control periods (a reading
 * is answered, decided and acted on one period apart each) plus 0.2 s to turn away. At the world
 * defaults (0.5 m/s, 32 ms, radius 0.12 m) the thresholds are the fixed ones the project used
 * before they were derived (0.15 m imminent, 0.22 m ahead, 0.15 m at a side, 0.20 m to a followed
 * wall); a faster robot looks further ahead, a larger one keeps its flanks further off, a small
 * slow one comes closer.
 *
 * @param imminentM     closer than this ahead: stop and turn on the spot
 * @param engageFrontM  anything within ±30° of the heading closer than this: take over
 * @param engageAheadM  anything within ±12° closer than this: take over
 * @param engageSideM   anything at a side (30° to 100°) closer than this: take over
 * @param wallDistanceM the distance kept to a followed boundary
 * @param releaseFrontM letting go needs this much free space ahead
 * @param releaseSideM  ... and the followed side's 45° sensor this clear
 */
public record Clearance(double imminentM, double engageFrontM, double engageAheadM, double engageSideM,
                        double wallDistanceM, double releaseFrontM, double releaseSideM) {

    /** The control period assumed until one is measured, milliseconds (the world files' default). */
    public static final long DEFAULT_PERIOD_MS = 32;
    /** The sensor range assumed when none is known, metres (the world files' default). */
    public static final double DEFAULT_RANGE_M = 1.0;
    /** Periods between a reading and the wheels obeying the command decided from it. */
    private static final int REACTION_PERIODS = 3;
    /** Time to turn away from an obstacle once the command arrives, seconds. */
    private static final double TURN_AWAY_S = 0.2;
    /** The body radius the fixed thresholds were tuned for, metres. */
    private static final double REFERENCE_RADIUS_M = 0.12;
    /** The speed term the fixed thresholds were tuned for (0.5 m/s over 0.296 s), metres. */
    private static final double REFERENCE_SPEED_TERM_M = 0.148;

    /** The thresholds at the world defaults. */
    public static final Clearance DEFAULT = of(DriveProfile.DEFAULT, DEFAULT_PERIOD_MS, DEFAULT_RANGE_M);

    /**
     * @param profile  the robot's top speed and axle width
     * @param periodMs the control period, milliseconds (the time between two readings)
     * @param rangeM   the distance sensors' range, metres
     * @return the thresholds for that robot; none beyond 90 % of the range, which a free ray reads
     */
    public static Clearance of(DriveProfile profile, long periodMs, double rangeM) {
        double speedTermM = profile.maxSpeedMps() * (REACTION_PERIODS * periodMs / 1000.0 + TURN_AWAY_S);
        double bodyTermM = Math.max(0.0, profile.axleWidthM() / 2 - REFERENCE_RADIUS_M);
        double speedExtraM = speedTermM - REFERENCE_SPEED_TERM_M;
        double cap = 0.9 * rangeM;
        double imminent = Math.min(cap, Math.max(0.05, speedTermM + 0.002));
        double front = Math.min(cap, imminent + 0.07);
        double ahead = Math.min(cap, imminent + 0.15);
        double side = Math.min(cap, Math.max(0.06, 0.15 + 0.5 * bodyTermM + 0.25 * speedExtraM));
        double wall = Math.min(cap, Math.max(side + 0.03, 0.20 + 0.5 * bodyTermM + 0.25 * speedExtraM));
        double releaseFront = Math.min(cap, Math.max(0.45, ahead + 0.15));
        double releaseSide = Math.min(cap, wall + 0.05);
        return new Clearance(imminent, front, ahead, side, wall, releaseFront, releaseSide);
    }
}
