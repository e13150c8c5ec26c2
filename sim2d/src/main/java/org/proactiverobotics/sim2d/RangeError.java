package org.proactiverobotics.sim2d;

/**
 * The part of a distance sensor's error that grows with the distance, as a triangulation lidar's does: its
 * standard deviation is a fixed fraction of the distance read. It adds to the sensor's constant
 * {@link SensorNoise#distanceSigmaM()}.
 *
 * @param fractionOfRange the standard deviation per metre of distance read (0.01 is 1 % of the distance)
 */
public record RangeError(double fractionOfRange) {

    /** No distance-proportional error. */
    public static final RangeError NONE = new RangeError(0.0);

    /** Refuses a negative or non-finite fraction. */
    public RangeError {
        SensorNoise.check(fractionOfRange, "rangeError.fractionOfRange");
    }

    /**
     * @param distanceM the true distance, metres
     * @return this part's standard deviation at that distance, metres
     */
    public double sigmaAtM(double distanceM) {
        return fractionOfRange * distanceM;
    }
}
