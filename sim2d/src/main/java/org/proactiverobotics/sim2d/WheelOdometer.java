package org.proactiverobotics.sim2d;

/**
 * The robot's wheel encoders, Webots-style: how far each wheel has rolled since the simulation
 * began, in metres, positive forwards. Each step adds the wheel speed the simulator applied times
 * the step's length (nothing while the battery is empty); a wheel pushing against a wall still
 * rolls, as a real wheel slips and its encoder counts on. Exact under every noise level:
 * {@link SensorNoise} has no channel for it. Under {@link WheelSlip} the encoders still count the
 * commanded travel while the body moves less: the error odometry has.
 */
public final class WheelOdometer {

    private final WorldRobot owner;

    WheelOdometer(WorldRobot owner) {
        this.owner = owner;
    }

    /** @return a new array {left, right}: each wheel's travel since the start, metres (backwards negative) */
    public double[] getTravelM() {
        return owner.wheelTravelM();
    }
}
