package com.example.park;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** Once every checkpoint is reached, drives back to the recharge station and parks there: one rule, {@link Park}. */
public final class ReturnToStationScenario implements Scenario {

    /** The name strategies and traces know the scenario by. */
    public static final String NAME = "ReturnToStation";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public List<Rule> firstRules() {
        return List.of(new Park());
    }
}
