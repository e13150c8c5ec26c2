package org.proactiverobotics.testkit;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One decision of the DecisionMaking scenario, as it saw the CommandArray: the live
 * suggestions, the winner by the strategy, and the command it decided (sent to the robot in
 * the next iteration).
 *
 * @param iteration   the engine iteration that decided
 * @param suggestions each scenario's live suggestion, by scenario name, in slot order
 * @param winner      the scenario whose suggestion won; {@code DecisionMaking} when no scenario
 *                    suggested anything and the robot is told to stop
 * @param command     the winning command, in the robot's grammar (e.g. {@code FORWARD 0.1})
 */
public record Decision(long iteration, Map<String, String> suggestions, String winner, String command) {

    /** Copies the suggestions. */
    public Decision {
        suggestions = Collections.unmodifiableMap(new LinkedHashMap<>(suggestions));
    }
}
