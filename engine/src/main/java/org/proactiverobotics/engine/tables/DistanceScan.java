package org.proactiverobotics.engine.tables;

/**
 * One reading of all distance sensors.
 *
 * @param simTimeMs  simulated time of the reading, milliseconds
 * @param anglesRad  each sensor's direction relative to the heading, radians (CCW positive)
 * @param distancesM each sensor's distance from the robot's rim to the nearest obstacle, metres
 * @param rangeM     the sensors' range, metres (a free ray reads this)
 */
public record DistanceScan(long simTimeMs, double[] anglesRad, double[] distancesM, double rangeM) {

    /**
     * The shortest distance among the sensors pointing within an angular sector.
     *
     * @param fromRad sector start, radians relative to the heading (inclusive)
     * @param toRad   sector end, radians (inclusive)
     * @return metres; the range when no sensor points there; a reading that is not a number or
     *         negative counts as 0 (an obstacle), never as free space
     */
    public double min(double fromRad, double toRad) {
        double min = rangeM;
        for (int i = 0; i < anglesRad.length; i++) {
            if (anglesRad[i] >= fromRad && anglesRad[i] <= toRad) {
                double d = distancesM[i];
                min = Math.min(min, d >= 0 ? d : 0.0); // NaN fails d >= 0
            }
        }
        return min;
    }

    /**
     * The free space within an angular sector, as the sum of its sensors' distances.
     *
     * @param fromRad sector start, radians (inclusive)
     * @param toRad   sector end, radians (inclusive)
     * @return metres
     */
    public double sum(double fromRad, double toRad) {
        double sum = 0;
        for (int i = 0; i < anglesRad.length; i++) {
            if (anglesRad[i] >= fromRad && anglesRad[i] <= toRad && distancesM[i] > 0) {
                sum += distancesM[i]; // NaN and negatives add no free space
            }
        }
        return sum;
    }
}
