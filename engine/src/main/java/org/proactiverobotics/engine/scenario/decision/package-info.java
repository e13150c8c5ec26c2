/**
 * Scenario 5, Decision making and strategy: ReadRobotCommands reads the PriorityArray and each
 * slot's time-out (the strategy table), takes the live CommandArray suggestion of the highest
 * priority and generates SendRobotCommand, which writes it to engine_comments (STOP instead,
 * when the winner's scenario has failed since). A suggestion older than its slot's time-out
 * (simulated ms; 0 = one iteration, the default) is cleared and the next priority wins.
 */
package org.proactiverobotics.engine.scenario.decision;
