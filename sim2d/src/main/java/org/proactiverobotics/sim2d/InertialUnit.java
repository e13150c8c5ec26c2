package org.proactiverobotics.sim2d;

/** The robot's inertial unit, Webots-style: orientation in radians, sampled after the last step. */
public final class InertialUnit {

    private final WorldRobot owner;

    InertialUnit(WorldRobot owner) {
        this.owner = owner;
    }

    /**
     * @return a new array {roll, pitch, yaw} in radians; roll and pitch are 0 in 2D; yaw is in (-π, π],
     * 0 along +x, counter-clockwise positive (with noise when the simulation has some)
     */
    public double[] getRollPitchYaw() {
        return new double[] {0.0, 0.0, owner.yawValue()};
    }
}
