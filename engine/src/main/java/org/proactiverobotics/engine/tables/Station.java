package org.proactiverobotics.engine.tables;

/**
 * The recharge station ({@code recharge_station} row).
 *
 * @param xM      x, metres
 * @param yM      y, metres
 * @param radiusM how close the robot must be to charge, metres
 */
public record Station(double xM, double yM, double radiusM) {
}
