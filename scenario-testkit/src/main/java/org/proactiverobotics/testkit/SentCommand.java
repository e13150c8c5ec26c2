package org.proactiverobotics.testkit;

/**
 * One command the engine sent to the robot: a row of {@code engine_comments}.
 *
 * @param iteration the engine iteration that sent it (the one after its decision)
 * @param simTimeMs the simulated time of the newest GPS reading it was based on, milliseconds
 * @param scenario  the scenario whose suggestion it was ({@code DecisionMaking} or
 *                  {@code FailSafe} for a STOP of their own)
 * @param command   the command, in the robot's grammar
 */
public record SentCommand(long iteration, long simTimeMs, String scenario, String command) {
}
