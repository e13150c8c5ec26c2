package com.example.traffic;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** A traffic rule for a world shared with other robots: veer right when something comes head-on. */
public final class KeepRightScenario implements Scenario {

    /** The name strategies and traces know the scenario by. */
    public static final String NAME = "KeepRight";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public List<Rule> firstRules() {
        return List.of(new PassOnTheRight());
    }
}
