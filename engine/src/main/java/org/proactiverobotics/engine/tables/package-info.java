/**
 * The robot tables as the engine side sees them: small interfaces, one per concern, that
 * scenarios ask the engine for as services ({@code ctx.service(SensorReadings.class)}), and
 * {@link org.proactiverobotics.engine.tables.JdbcRobotTables}, their implementation over the
 * shared database. Scenarios import these, never each other. Units: metres, radians, percent,
 * simulated milliseconds.
 */
package org.proactiverobotics.engine.tables;
