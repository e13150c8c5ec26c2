package org.proactiverobotics.robot.link;

/**
 * A battery reading.
 *
 * @param levelPct the level in percent (0-100)
 * @param charging whether the robot is charging
 */
public record BatteryReading(double levelPct, boolean charging) {
}
