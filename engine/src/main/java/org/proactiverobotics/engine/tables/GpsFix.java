package org.proactiverobotics.engine.tables;

/**
 * A GPS reading.
 *
 * @param simTimeMs simulated time of the reading, milliseconds
 * @param xM        x, metres
 * @param yM        y, metres
 */
public record GpsFix(long simTimeMs, double xM, double yM) {

    /** @return the distance to a point, metres */
    public double distanceTo(double x, double y) {
        return Math.hypot(x - xM, y - yM);
    }
}
