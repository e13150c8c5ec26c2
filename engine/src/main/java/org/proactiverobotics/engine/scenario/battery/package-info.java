/**
 * Scenario 4, Battery monitor: BatteryMonitor sends the robot to the recharge station at the
 * point of no return, whatever else happens, and before a leg it could not come back from; while
 * neither holds it clones itself, otherwise it generates MoveToRecharge, which drives to the
 * station round obstacles with the shared boundary-following reflex, recharges to the
 * battery_recharged level and hands back. Decides only from what the engine sees in the database. Suggests with {@code ctx.suggest}, in the
 * CommandArray slot the engine gives the scenario.
 */
package org.proactiverobotics.engine.scenario.battery;
