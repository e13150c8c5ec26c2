/**
 * How the engine turns a wish ("go there", "turn away") into wheel speeds for the robot's
 * commands: a library the scenarios share, not a scenario. The go-to law and the command text
 * ({@link org.proactiverobotics.engine.motion.Steering}), the collision reflex that vets a command
 * ({@link org.proactiverobotics.engine.motion.CollisionReflex}) and the distances it keeps,
 * derived from the robot's speed, clock, body and sensor range
 * ({@link org.proactiverobotics.engine.motion.Clearance}). Units: metres, seconds, radians.
 */
package org.proactiverobotics.engine.motion;
