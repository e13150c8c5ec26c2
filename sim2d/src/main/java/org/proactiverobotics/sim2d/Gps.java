package org.proactiverobotics.sim2d;

/**
 * The robot's GPS, Webots-style: position of the robot's centre in metres, sampled after the last step.
 * Without a fix (indoors) it reads NaN on both coordinates, as a Webots GPS does when it has nothing to say.
 */
public final class Gps {

    private final WorldRobot owner;

    Gps(WorldRobot owner) {
        this.owner = owner;
    }

    /** @return a new array {x, y} in metres (with noise when the simulation has some; NaN without a fix) */
    public double[] getValues() {
        return owner.gpsValues();
    }

    /** @return whether the GPS has a fix (false indoors: then {@link #getValues()} is NaN) */
    public boolean hasFix() {
        return owner.gpsFix();
    }
}
