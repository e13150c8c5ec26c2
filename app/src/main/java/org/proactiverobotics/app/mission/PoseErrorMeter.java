package org.proactiverobotics.app.mission;

/**
 * Accumulates the pose error of a mission, one sample per engine iteration: the distance between
 * the believed and the true position, and the absolute difference of their headings wrapped to
 * [0, π]. A few doubles, no object per sample, so that it can sit on the mission's hot path.
 * Deterministic: the same samples in the same order give the same figures, bit for bit.
 */
final class PoseErrorMeter {

    private static final double TWO_PI = 2 * Math.PI;

    private double sumM;
    private double maxM;
    private double sumHeadingRad;
    private double maxHeadingRad;
    private long samples;

    /**
     * Adds one iteration's sample.
     *
     * @param believedXM         the engine's x, metres
     * @param believedYM         the engine's y, metres
     * @param believedHeadingRad the engine's heading, radians (any turn: only the difference counts)
     * @param trueXM             the ground truth's x, metres
     * @param trueYM             the ground truth's y, metres
     * @param trueHeadingRad     the ground truth's heading, radians
     */
    void add(double believedXM, double believedYM, double believedHeadingRad, double trueXM, double trueYM,
             double trueHeadingRad) {
        double dx = believedXM - trueXM;
        double dy = believedYM - trueYM;
        double distance = Math.sqrt(dx * dx + dy * dy); // sqrt is exact in IEEE 754: the same bits on every machine
        double heading = Math.abs(Math.IEEEremainder(believedHeadingRad - trueHeadingRad, TWO_PI));
        sumM += distance;
        maxM = Math.max(maxM, distance);
        sumHeadingRad += heading;
        maxHeadingRad = Math.max(maxHeadingRad, heading);
        samples++;
    }

    /** @return the iterations measured so far */
    long samples() {
        return samples;
    }

    /**
     * @return the figures so far, rounded as report.json shows them (0.1 mm, 0.1 mrad); null when no
     *         iteration was measured (the engine never had a pose)
     */
    PoseError result() {
        if (samples == 0) {
            return null;
        }
        return new PoseError(round(sumM / samples), round(maxM), round(sumHeadingRad / samples), round(maxHeadingRad),
                samples);
    }

    private static double round(double value) {
        return MissionReport.round(value, 4);
    }
}
