/**
 * Scenario 2, Reach destination: GetCheckpoint finds the first checkpoint not yet reached and
 * generates MoveToCheckpoint, which steers toward it until it is reached, marks it, and hands
 * back to GetCheckpoint. Suggests in CommandArray slot {@value
 * org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario#SLOT}.
 */
package org.proactiverobotics.engine.scenario.destination;
