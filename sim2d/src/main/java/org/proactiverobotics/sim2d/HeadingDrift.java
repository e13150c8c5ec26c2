package org.proactiverobotics.sim2d;

/**
 * The drift of a heading integrated from a MEMS gyroscope: the gyro's residual bias (what remains after
 * calibrating it at rest, drawn once per run) turns into a heading error that grows linearly in time, and its
 * white rate noise (angle random walk) into one that grows with the square root of time. Unbounded, as a
 * gyro-only heading is.
 *
 * @param biasSigmaRadPerS           standard deviation of the residual gyro bias, radians per second
 * @param angleRandomWalkRadPerSqrtS the angle random walk, radians per √second (rate noise spectral density)
 */
public record HeadingDrift(double biasSigmaRadPerS, double angleRandomWalkRadPerSqrtS) {

    /** No drift. */
    public static final HeadingDrift NONE = new HeadingDrift(0.0, 0.0);

    /** Refuses negative or non-finite figures. */
    public HeadingDrift {
        SensorNoise.check(biasSigmaRadPerS, "headingDrift.biasSigmaRadPerS");
        SensorNoise.check(angleRandomWalkRadPerSqrtS, "headingDrift.angleRandomWalkRadPerSqrtS");
    }

    /** @return whether the heading never drifts */
    public boolean isNone() {
        return biasSigmaRadPerS == 0.0 && angleRandomWalkRadPerSqrtS == 0.0;
    }

    /**
     * @param gaussian a draw from N(0, 1)
     * @return this run's residual gyro bias, radians per second
     */
    public double bias(double gaussian) {
        return biasSigmaRadPerS * gaussian;
    }

    /**
     * @param errorRad      the heading error before the step, radians
     * @param biasRadPerS   this run's gyro bias, radians per second
     * @param dtS           the step, seconds
     * @param gaussian      a draw from N(0, 1)
     * @return the heading error after the step, radians
     */
    public double next(double errorRad, double biasRadPerS, double dtS, double gaussian) {
        return errorRad + biasRadPerS * dtS + angleRandomWalkRadPerSqrtS * StrictMath.sqrt(dtS) * gaussian;
    }
}
