package org.proactiverobotics.sim2d;

/**
 * A GPS error that wanders: a first-order Gauss–Markov bias on each coordinate, as an RTK float or a
 * multipath-degraded fix drifts slowly around the true position. Stationary: at every step the bias is
 * distributed N(0, σ²); two values {@code t} seconds apart correlate by {@code exp(-t / τ)}.
 *
 * @param sigmaM            the bias's standard deviation on each coordinate, metres (0 for none)
 * @param correlationTimeS  its correlation time τ, seconds (how slowly it wanders)
 */
public record GpsBias(double sigmaM, double correlationTimeS) {

    /** No bias. */
    public static final GpsBias NONE = new GpsBias(0.0, 1.0);

    /** Refuses negative or non-finite figures and a correlation time that is not positive. */
    public GpsBias {
        SensorNoise.check(sigmaM, "gpsBias.sigmaM");
        if (!Double.isFinite(correlationTimeS) || correlationTimeS <= 0.0) {
            throw new IllegalArgumentException("gpsBias.correlationTimeS must be finite and > 0, got " + correlationTimeS);
        }
    }

    /** @return whether the bias is always zero */
    public boolean isNone() {
        return sigmaM == 0.0;
    }

    /**
     * @param gaussian a draw from N(0, 1)
     * @return the bias at the start, metres (drawn from the stationary distribution)
     */
    public double initial(double gaussian) {
        return sigmaM * gaussian;
    }

    /**
     * One step of the process: {@code b' = φ·b + σ·√(1-φ²)·w}, {@code φ = exp(-dt / τ)}, which keeps the variance σ².
     *
     * @param biasM    the bias before the step, metres
     * @param dtS      the step, seconds
     * @param gaussian a draw from N(0, 1)
     * @return the bias after the step, metres
     */
    public double next(double biasM, double dtS, double gaussian) {
        double phi = StrictMath.exp(-dtS / correlationTimeS);
        return phi * biasM + sigmaM * StrictMath.sqrt(1.0 - phi * phi) * gaussian;
    }
}
