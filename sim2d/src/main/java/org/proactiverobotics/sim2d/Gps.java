package org.proactiverobotics.sim2d;

/**
 * The robot's GPS, Webots-style: position of the robot's centre in metres, sampled after the last step.
 * Without a fix (indoors) it reads NaN on both coordinates, as a Webots GPS does when it has nothing to say.
 */
public final class Gps {

    private final Simulation sim;

    Gps(Simulation sim) {
        this.sim = sim;
    }

    /** @return a new array {x, y} in metres (with noise when the simulation has some; NaN without a fix) */
    public double[] getValues() {
        return sim.gpsValues();
    }

    /** @return whether the GPS has a fix (false indoors: then {@link #getValues()} is NaN) */
    public boolean hasFix() {
        return sim.noise().gpsFix();
    }
}
