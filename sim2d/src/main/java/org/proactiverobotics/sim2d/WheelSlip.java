package org.proactiverobotics.sim2d;

/**
 * Wheel slip: each wheel travels a little less (or more) than commanded. Each step, each wheel's actual speed
 * is its commanded speed times {@code 1 - meanFraction + sigmaFraction·w} (w from N(0, 1), a draw per wheel per
 * step, never below 0). An error of the motion, not of a sensor: the robot really moves that way.
 *
 * @param meanFraction  the travel lost on average, as a fraction of the commanded travel (0.02 is 2 %)
 * @param sigmaFraction the standard deviation of each wheel's step-to-step slip, as a fraction
 */
public record WheelSlip(double meanFraction, double sigmaFraction) {

    /** No slip. */
    public static final WheelSlip NONE = new WheelSlip(0.0, 0.0);

    /** Refuses negative or non-finite figures and a mean of all the travel or more. */
    public WheelSlip {
        SensorNoise.check(meanFraction, "wheelSlip.meanFraction");
        SensorNoise.check(sigmaFraction, "wheelSlip.sigmaFraction");
        if (meanFraction >= 1.0) {
            throw new IllegalArgumentException("wheelSlip.meanFraction must be below 1, got " + meanFraction);
        }
    }

    /** @return whether the wheels never slip */
    public boolean isNone() {
        return meanFraction == 0.0 && sigmaFraction == 0.0;
    }

    /**
     * @param gaussian a draw from N(0, 1)
     * @return the factor of one wheel's commanded speed it actually achieves this step (at least 0)
     */
    public double factor(double gaussian) {
        return Math.max(0.0, 1.0 - meanFraction + sigmaFraction * gaussian);
    }
}
