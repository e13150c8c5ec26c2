package org.proactiverobotics.sim2d;

/**
 * The state of the errors that carry over from step to step (the GPS bias, the heading drift) and the wheel
 * slip of each step. Advanced once per simulation step, whether or not anything reads the sensors, so the
 * errors are a pure function of the seed and the step. Each error draws from a stream of its own (the seed
 * mixed with a constant), apart from the white noise's, so none of the white draws shifts.
 */
final class SensorErrors {

    /** Stream of the GPS bias: channel 0 for x, 1 for y. */
    private static final long GPS_BIAS_STREAM = 0x6A09E667F3BCC909L;
    /** Stream of the heading drift: channel 0 for the gyro bias (step 0 only), 1 for the random walk. */
    private static final long HEADING_STREAM = 0xBB67AE8584CAA73BL;
    /** Stream of the wheel slip: channel 0 for the left wheel, 1 for the right. */
    private static final long SLIP_STREAM = 0x3C6EF372FE94F82BL;

    private final SensorNoise noise;
    private final long seed;
    private final double dtS;
    private final double gyroBiasRadPerS;
    private double gpsBiasXM;
    private double gpsBiasYM;
    private double headingErrorRad;

    /**
     * @param noise the errors to simulate
     * @param seed  the world's seed
     * @param dtS   the simulation step, seconds
     */
    SensorErrors(SensorNoise noise, long seed, double dtS) {
        this.noise = noise;
        this.seed = seed;
        this.dtS = dtS;
        GpsBias bias = noise.gpsBias();
        if (!bias.isNone()) {
            gpsBiasXM = bias.initial(SensorNoise.gaussian(seed ^ GPS_BIAS_STREAM, 0, 0));
            gpsBiasYM = bias.initial(SensorNoise.gaussian(seed ^ GPS_BIAS_STREAM, 0, 1));
        }
        HeadingDrift drift = noise.headingDrift();
        gyroBiasRadPerS = drift.isNone() ? 0.0 : drift.bias(SensorNoise.gaussian(seed ^ HEADING_STREAM, 0, 0));
    }

    /**
     * Moves the carried-over errors on by one step.
     *
     * @param step the step just reached (1 after the first step)
     */
    void advance(long step) {
        GpsBias bias = noise.gpsBias();
        if (!bias.isNone()) {
            gpsBiasXM = bias.next(gpsBiasXM, dtS, SensorNoise.gaussian(seed ^ GPS_BIAS_STREAM, step, 0));
            gpsBiasYM = bias.next(gpsBiasYM, dtS, SensorNoise.gaussian(seed ^ GPS_BIAS_STREAM, step, 1));
        }
        HeadingDrift drift = noise.headingDrift();
        if (!drift.isNone()) {
            headingErrorRad = drift.next(headingErrorRad, gyroBiasRadPerS, dtS,
                    SensorNoise.gaussian(seed ^ HEADING_STREAM, step, 1));
        }
    }

    /** @return the GPS bias on x now, metres */
    double gpsBiasXM() {
        return gpsBiasXM;
    }

    /** @return the GPS bias on y now, metres */
    double gpsBiasYM() {
        return gpsBiasYM;
    }

    /** @return the heading's drift now, radians */
    double headingErrorRad() {
        return headingErrorRad;
    }

    /**
     * @param step  the step about to be taken (0 for the first)
     * @param wheel 0 for the left wheel, 1 for the right
     * @return the factor of that wheel's commanded speed it achieves during the step
     */
    double slipFactor(long step, int wheel) {
        return noise.wheelSlip().factor(SensorNoise.gaussian(seed ^ SLIP_STREAM, step, wheel));
    }
}
