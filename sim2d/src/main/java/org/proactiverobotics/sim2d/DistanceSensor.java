package org.proactiverobotics.sim2d;

/**
 * One distance sensor, Webots-style: a ray from the robot's rim, at a fixed angle to its heading, that
 * reads the distance in metres to the nearest wall, obstacle or other robot, or its range when nothing is that close.
 */
public final class DistanceSensor {

    private final WorldRobot owner;
    private final int index;
    private final double angleRad;
    private final double rangeM;

    DistanceSensor(WorldRobot owner, int index, double angleRad, double rangeM) {
        this.owner = owner;
        this.index = index;
        this.angleRad = angleRad;
        this.rangeM = rangeM;
    }

    /** @return this sensor's index, 0 for the rightmost, counting counter-clockwise */
    public int getIndex() {
        return index;
    }

    /** @return the ray's angle relative to the robot's heading, radians (counter-clockwise positive) */
    public double getAngleRad() {
        return angleRad;
    }

    /** @return the longest distance this sensor reads, metres */
    public double getRangeM() {
        return rangeM;
    }

    /**
     * @return the distance in metres from the robot's rim to the nearest wall, obstacle or other robot along the ray,
     * {@link #getRangeM()} when nothing is hit within range (0 when touching); sampled after the last step
     */
    public double getValue() {
        return owner.distanceValue(index);
    }
}
