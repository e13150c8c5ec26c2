package org.proactiverobotics.engine.scenario.decision;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** Scenario 5: picks, by priority, the suggestion the robot gets. Started last, so it runs last. */
public final class DecisionMakingScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "DecisionMaking";

    @Override
    public String name() {
        return NAME;
    }

    /** Active from the start: the meta-rule generates these at once. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new ReadRobotCommands());
    }
}
