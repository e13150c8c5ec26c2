package org.proactiverobotics.engine.scenario.destination;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** Scenario 2: moves the robot to its checkpoints, in order. */
public final class ReachDestinationScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "ReachDestination";

    @Override
    public String name() {
        return NAME;
    }

    /** Active from the start: the meta-rule generates these at once. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new GetCheckpoint());
    }
}
