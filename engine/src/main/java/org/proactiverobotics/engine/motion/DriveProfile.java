package org.proactiverobotics.engine.motion;

/**
 * What the engine assumes of the robot's drive when it computes wheel speeds.
 *
 * @param maxSpeedMps the highest wheel speed the robot accepts, metres per second
 * @param axleWidthM  the distance between the wheels, metres
 */
public record DriveProfile(double maxSpeedMps, double axleWidthM) {

    /** The defaults of a world file's robot: 0.5 m/s, 0.24 m between the wheels. */
    public static final DriveProfile DEFAULT = new DriveProfile(0.5, 0.24);

    /** Checks both values. */
    public DriveProfile {
        if (!(maxSpeedMps > 0) || !Double.isFinite(maxSpeedMps)) {
            throw new IllegalArgumentException("maxSpeedMps must be a positive number: " + maxSpeedMps);
        }
        if (!(axleWidthM > 0) || !Double.isFinite(axleWidthM)) {
            throw new IllegalArgumentException("axleWidthM must be a positive number: " + axleWidthM);
        }
    }
}
