package org.proactiverobotics.sim2d;

/**
 * The robot's battery, in percent. It drains per metre travelled; at 0 the robot cannot move. It charges
 * only at the recharge station, after the robot asks, until it reaches the world's {@code rechargeTo}.
 */
public final class Battery {

    private final WorldRobot owner;

    Battery(WorldRobot owner) {
        this.owner = owner;
    }

    /** @return the charge, percent (0–100) */
    public double getLevelPct() {
        return owner.batteryLevel();
    }

    /** @return whether the battery is charging now */
    public boolean isCharging() {
        return owner.isCharging();
    }

    /** @return whether the robot's centre is within the recharge station */
    public boolean isAtStation() {
        return owner.isAtStation();
    }

    /**
     * Starts a charging session; takes effect only while at the station and below {@code rechargeTo}.
     * Charging stops by itself at {@code rechargeTo} or when the robot leaves the station.
     *
     * @return whether the battery is charging
     */
    public boolean startCharging() {
        return owner.startCharging();
    }

    /** Stops charging (no effect when not charging). */
    public void stopCharging() {
        owner.stopCharging();
    }
}
