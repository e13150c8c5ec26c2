/**
 * Scenario 4, Battery monitor: BatteryMonitor asks whether the robot can reach its next
 * checkpoint and still get to the recharge station; while yes it clones itself, if not it
 * generates MoveToRecharge, which drives to the station, recharges to the battery_recharged
 * level and hands back. Decides only from what the engine sees in the database. Suggests with {@code ctx.suggest}, in the
 * CommandArray slot the engine gives the scenario.
 */
package org.proactiverobotics.engine.scenario.battery;
