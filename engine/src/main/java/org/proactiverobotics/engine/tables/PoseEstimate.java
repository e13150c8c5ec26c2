package org.proactiverobotics.engine.tables;

/**
 * The engine's estimate of the robot's pose ({@code pose_estimate}), kept by the localisation
 * scenario: what every scenario that needs the robot's position or heading reads, never the raw
 * GPS. The covariance is the estimate's uncertainty: its square roots are standard deviations.
 * The heading is NaN while it is not known (a robot with a GPS fix and no inertial unit yet).
 *
 * @param simTimeMs simulated time of the newest reading it includes, milliseconds
 * @param xM        x, metres
 * @param yM        y, metres
 * @param yawRad    heading, radians, counter-clockwise from +x
 * @param varX      variance of x, square metres
 * @param varY      variance of y, square metres
 * @param varYaw    variance of the heading, square radians
 * @param covXY     covariance of x and y, square metres
 * @param covXYaw   covariance of x and the heading, metre-radians
 * @param covYYaw   covariance of y and the heading, metre-radians
 */
public record PoseEstimate(long simTimeMs, double xM, double yM, double yawRad,
                           double varX, double varY, double varYaw, double covXY, double covXYaw, double covYYaw) {

    /**
     * @param simTimeMs simulated time, milliseconds
     * @param xM        x, metres
     * @param yM        y, metres
     * @param yawRad    heading, radians
     * @return a pose known exactly (no covariance): what a test scripts
     */
    public static PoseEstimate exact(long simTimeMs, double xM, double yM, double yawRad) {
        return new PoseEstimate(simTimeMs, xM, yM, yawRad, 0, 0, 0, 0, 0, 0);
    }

    /** @return whether the heading is known (it is NaN until the inertial unit or odometry tell it) */
    public boolean knowsHeading() {
        return !Double.isNaN(yawRad);
    }

    /** @return the distance to a point, metres */
    public double distanceTo(double x, double y) {
        return Math.hypot(x - xM, y - yM);
    }

    /** @return the standard deviation of the position along its least certain direction, metres */
    public double positionSigmaM() {
        double mean = (varX + varY) / 2;
        double half = Math.sqrt(Math.max(0, (varX - varY) * (varX - varY) / 4 + covXY * covXY));
        return Math.sqrt(Math.max(0, mean + half));
    }
}
