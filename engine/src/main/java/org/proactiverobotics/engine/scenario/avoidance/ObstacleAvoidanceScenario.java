package org.proactiverobotics.engine.scenario.avoidance;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** Scenario 3: keeps the robot off obstacles and gets it around them. */
public final class ObstacleAvoidanceScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "ObstacleAvoidance";

    @Override
    public String name() {
        return NAME;
    }

    /** Active from the start: the meta-rule generates these at once. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new AvoidObstacles());
    }
}
