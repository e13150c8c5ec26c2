/**
 * The words both sides write and read in the shared tables, defined once: the sensors a request
 * names ({@code sensor_requests.sensor}), the timing of a run ({@code robot_clock.timing}) and its
 * state ({@code robot_clock.state}). The engine and the robot controller never depend on each
 * other; they meet in the database, and in these words.
 */
package org.proactiverobotics.protocol;
