package org.proactiverobotics.engine;

/**
 * A command a scenario suggests for the robot, as held in a {@link CommandArray} slot.
 *
 * @param command   the command text, e.g. {@code "DRIVE 0.40 0.35"}
 * @param scenario  the scenario that entered it
 * @param iteration the iteration in which it was entered
 */
public record Suggestion(String command, String scenario, long iteration) {
}
