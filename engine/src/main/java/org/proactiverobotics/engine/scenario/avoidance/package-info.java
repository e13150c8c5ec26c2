/**
 * Scenario 3, Obstacle avoidance: AvoidObstacles follows an obstacle's boundary when one is too
 * close, and lets go when the way is clear and the heading is back where it was. Suggests with {@code ctx.suggest}, in the
 * CommandArray slot the engine gives the scenario.
 */
package org.proactiverobotics.engine.scenario.avoidance;
