package org.proactiverobotics.engine.scenario.failsafe;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/**
 * The fail-safe scenario: keeps a failing scenario's word from the robot and brings a scenario
 * that failed for good back. Start it after the scenarios that suggest and before the decision.
 */
public final class FailSafeScenario implements Scenario {

    /** The scenario's name in configuration and records (and in engine_comments for its STOPs). */
    public static final String NAME = "FailSafe";

    @Override
    public String name() {
        return NAME;
    }

    /** Active from the start: the meta-rule generates it at once. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new WatchFailures());
    }
}
