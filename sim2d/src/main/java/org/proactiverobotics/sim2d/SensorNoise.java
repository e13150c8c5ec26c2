package org.proactiverobotics.sim2d;

/**
 * The sensors' errors and the wheels' slip; zero for none.
 * <p>
 * White Gaussian noise on each reading ({@link #gpsSigmaM}, {@link #yawSigmaRad}, {@link #distanceSigmaM}), and the
 * errors real sensors have beyond it: a wandering GPS bias, a drifting gyro heading, a distance error that grows
 * with the distance, wheel slip; and whether the GPS has a fix at all (indoors it has none: it reads NaN).
 * Noise is not part of the world file (its format is a contract); the caller chooses it when creating the
 * {@link Simulation}. Draws are a pure function of the world's seed, the step number and the channel, so
 * readings are the same bit for bit however often (or seldom) a controller reads them; the errors beyond white
 * noise draw from streams of their own, so adding them shifts none of the white draws.
 *
 * @param gpsSigmaM      white noise on each GPS coordinate, metres
 * @param yawSigmaRad    white noise on the inertial unit's yaw, radians
 * @param distanceSigmaM white noise on each distance sensor, metres (the reading stays within 0..range)
 * @param rangeError     the distance sensors' error that grows with the distance
 * @param gpsBias        the GPS's wandering bias
 * @param headingDrift   the inertial unit's heading drift
 * @param wheelSlip      the wheels' slip (moves the robot, not a reading)
 * @param gpsFix         whether the GPS has a fix; without one it reads NaN (no absolute position, as indoors)
 */
public record SensorNoise(double gpsSigmaM, double yawSigmaRad, double distanceSigmaM, RangeError rangeError,
                          GpsBias gpsBias, HeadingDrift headingDrift, WheelSlip wheelSlip, boolean gpsFix) {

    /** Perfect sensors. */
    public static final SensorNoise NONE = new SensorNoise(0.0, 0.0, 0.0);

    /** Small noise, roughly that of Webots' default devices: 1 cm GPS, 0.5° yaw, 1 cm distance. */
    public static final SensorNoise SMALL = new SensorNoise(0.01, Math.toRadians(0.5), 0.01);

    /** Refuses negative or non-finite deviations and missing error models. */
    public SensorNoise {
        check(gpsSigmaM, "gpsSigmaM");
        check(yawSigmaRad, "yawSigmaRad");
        check(distanceSigmaM, "distanceSigmaM");
        if (rangeError == null || gpsBias == null || headingDrift == null || wheelSlip == null) {
            throw new IllegalArgumentException("rangeError, gpsBias, headingDrift and wheelSlip must be given (NONE for none)");
        }
    }

    /**
     * White noise only, a GPS with a fix, no error beyond.
     *
     * @param gpsSigmaM      on each GPS coordinate, metres
     * @param yawSigmaRad    on the inertial unit's yaw, radians
     * @param distanceSigmaM on each distance sensor, metres
     */
    public SensorNoise(double gpsSigmaM, double yawSigmaRad, double distanceSigmaM) {
        this(gpsSigmaM, yawSigmaRad, distanceSigmaM, RangeError.NONE, GpsBias.NONE, HeadingDrift.NONE, WheelSlip.NONE, true);
    }

    /** @return the same errors with a GPS that never has a fix */
    public SensorNoise withoutGps() {
        return new SensorNoise(gpsSigmaM, yawSigmaRad, distanceSigmaM, rangeError, gpsBias, headingDrift, wheelSlip, false);
    }

    /**
     * @param distanceM the true distance, metres
     * @return the standard deviation of a distance reading at that distance, metres
     */
    public double distanceSigmaAtM(double distanceM) {
        return distanceSigmaM + rangeError.sigmaAtM(distanceM);
    }

    static void check(double v, String name) {
        if (!Double.isFinite(v) || v < 0) {
            throw new IllegalArgumentException(name + " must be finite and >= 0, got " + v);
        }
    }

    /** @return whether every deviation is zero, nothing slips and the GPS has a fix */
    public boolean isNone() {
        return gpsSigmaM == 0.0 && yawSigmaRad == 0.0 && distanceSigmaM == 0.0 && rangeError.fractionOfRange() == 0.0
                && gpsBias.isNone() && headingDrift.isNone() && wheelSlip.isNone() && gpsFix;
    }

    /**
     * A standard normal draw that depends only on its arguments (counter-based, no state).
     *
     * @param seed    the world's seed
     * @param step    the step number
     * @param channel which reading (one per sensor value)
     * @return a draw from N(0, 1)
     */
    static double gaussian(long seed, long step, int channel) {
        long h = mix(seed ^ mix(step * 0x9E3779B97F4A7C15L + channel));
        long h2 = mix(h + 0x9E3779B97F4A7C15L);
        // Box-Muller on two uniforms in (0, 1]; 53-bit mantissas as SplittableRandom does.
        double u1 = ((h >>> 11) + 1) * 0x1.0p-53;
        double u2 = (h2 >>> 11) * 0x1.0p-53;
        return StrictMath.sqrt(-2.0 * StrictMath.log(u1)) * StrictMath.cos(2.0 * Math.PI * u2);
    }

    /**
     * The seed of one robot's noise streams: robot 0 draws from the world's seed itself (a one-robot world reads
     * what it read before fleets), every other robot from a seed mixed with its index, so no two robots share a
     * stream.
     *
     * @param seed  the world's seed
     * @param index the robot's position in the world's robots (0-based)
     * @return the seed its draws use
     */
    static long robotSeed(long seed, int index) {
        return index == 0 ? seed : mix(seed ^ mix(0xD1B54A32D192ED03L * index));
    }

    /** SplitMix64's finaliser. */
    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
