package org.proactiverobotics.engine.tables;

/**
 * A battery reading.
 *
 * @param simTimeMs simulated time of the reading, milliseconds
 * @param levelPct  charge, percent (0-100)
 * @param charging  whether the robot was charging
 */
public record BatteryState(long simTimeMs, double levelPct, boolean charging) {
}
