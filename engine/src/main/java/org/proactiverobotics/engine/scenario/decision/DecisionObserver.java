package org.proactiverobotics.engine.scenario.decision;

import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.Suggestion;

/**
 * Told of every decision, for traces and reports. Register one as an engine service; none is
 * needed.
 */
public interface DecisionObserver {

    /**
     * @param iteration   the iteration that decided
     * @param suggestions the CommandArray as the decision saw it (valid during the call only)
     * @param winner      the suggestion that won; its scenario is {@value DecisionMakingScenario#NAME}
     *                    when every slot was empty and the robot is told to stop
     */
    void decided(long iteration, CommandArray suggestions, Suggestion winner);
}
