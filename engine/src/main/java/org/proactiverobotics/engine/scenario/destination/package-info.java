/**
 * Scenario 2, Reach destination: GetCheckpoint finds the first checkpoint not yet reached and
 * generates MoveToCheckpoint, which steers toward it until it is reached, marks it, and hands
 * back to GetCheckpoint. In a world shared with other robots, once every checkpoint is reached,
 * ReturnToStart drives the robot back to where it started, out of the others' way. Suggests with
 * {@code ctx.suggest}, in the
 * CommandArray slot the engine gives the scenario.
 */
package org.proactiverobotics.engine.scenario.destination;
