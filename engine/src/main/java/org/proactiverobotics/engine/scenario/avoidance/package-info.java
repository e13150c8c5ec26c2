/**
 * Scenario 3, Obstacle avoidance: AvoidObstacles follows an obstacle's boundary when one is too
 * close, and lets go when the way is clear and the heading is back where it was. Suggests in
 * CommandArray slot {@value org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario#SLOT}.
 */
package org.proactiverobotics.engine.scenario.avoidance;
