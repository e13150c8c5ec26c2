package org.proactiverobotics.engine;

import java.util.List;

/**
 * What one rule did in one iteration, for listeners.
 *
 * @param iteration the iteration
 * @param position  the rule's position in currentQueue (0 = first run)
 * @param rule      the rule (a live object: read it now, it may change in later iterations)
 * @param partsRun  the parts that ran, in order (the failed part included)
 * @param outcome   what the guards and conditions gave, or {@link Outcome#FAILED}
 * @param failure   the failure when {@code outcome} is FAILED, else null
 * @param generated the rules it generated, in order (none when it failed)
 */
public record RuleTrace(long iteration, int position, Rule rule, List<Part> partsRun, Outcome outcome,
                        RuleFailure failure, List<Rule> generated) {
}
