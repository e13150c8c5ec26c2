package org.proactiverobotics.sim2d;

/** The robot's GPS, Webots-style: position of the robot's centre in metres, sampled after the last step. */
public final class Gps {

    private final Simulation sim;

    Gps(Simulation sim) {
        this.sim = sim;
    }

    /** @return a new array {x, y} in metres (with noise when the simulation has some) */
    public double[] getValues() {
        return sim.gpsValues();
    }
}
