package com.example.governor;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** Slows the robot down near obstacles: one rule, {@link Govern}, running the whole mission. */
public final class SpeedGovernorScenario implements Scenario {

    /** The name strategies and traces know the scenario by. */
    public static final String NAME = "SpeedGovernor";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public List<Rule> firstRules() {
        return List.of(new Govern());
    }
}
