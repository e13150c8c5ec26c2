package org.proactiverobotics.sim2d;

/**
 * Gaussian noise added to sensor readings; standard deviations, zero for none.
 * <p>
 * Noise is not part of the world file (its format is a contract); the caller chooses it when creating the
 * {@link Simulation}. Draws are a pure function of the world's seed, the step number and the channel, so
 * readings are the same bit for bit however often (or seldom) a controller reads them.
 *
 * @param gpsSigmaM      on each GPS coordinate, metres
 * @param yawSigmaRad    on the inertial unit's yaw, radians
 * @param distanceSigmaM on each distance sensor, metres (the reading stays within 0..range)
 */
public record SensorNoise(double gpsSigmaM, double yawSigmaRad, double distanceSigmaM) {

    /** Perfect sensors. */
    public static final SensorNoise NONE = new SensorNoise(0.0, 0.0, 0.0);

    /** Small noise, roughly that of Webots' default devices: 1 cm GPS, 0.5° yaw, 1 cm distance. */
    public static final SensorNoise SMALL = new SensorNoise(0.01, Math.toRadians(0.5), 0.01);

    /** Refuses negative or non-finite deviations. */
    public SensorNoise {
        check(gpsSigmaM, "gpsSigmaM");
        check(yawSigmaRad, "yawSigmaRad");
        check(distanceSigmaM, "distanceSigmaM");
    }

    private static void check(double v, String name) {
        if (!Double.isFinite(v) || v < 0) {
            throw new IllegalArgumentException(name + " must be finite and >= 0, got " + v);
        }
    }

    /** @return whether every deviation is zero */
    public boolean isNone() {
        return gpsSigmaM == 0.0 && yawSigmaRad == 0.0 && distanceSigmaM == 0.0;
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

    /** SplitMix64's finaliser. */
    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
