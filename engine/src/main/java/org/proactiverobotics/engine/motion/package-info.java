/**
 * How the engine turns a wish ("go there", "turn away") into wheel speeds for the robot's
 * commands: a library the scenarios share, not a scenario. Units: metres, seconds, radians.
 */
package org.proactiverobotics.engine.motion;
