/**
 * The traffic scenario (Yield), run only in a world shared with other robots: the robot gives way
 * to something that comes at it head-on (backs off, waits a time its own id sets, tries again) and
 * waits near a recharge station that something occupies. It knows other robots only as its rays
 * see them; its rules read the pose, the scan, the battery, the station and the map like any
 * scenario's, and its commands are ranked by the strategy like any other.
 */
package org.proactiverobotics.engine.scenario.traffic;
