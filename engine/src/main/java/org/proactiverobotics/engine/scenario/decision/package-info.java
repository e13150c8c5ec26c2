/**
 * Scenario 5, Decision making and strategy: ReadRobotCommands reads the PriorityArray (the
 * strategy table), takes the CommandArray suggestion of the highest priority that holds one and
 * generates SendRobotCommand, which writes it to engine_comments.
 */
package org.proactiverobotics.engine.scenario.decision;
