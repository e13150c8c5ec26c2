package org.proactiverobotics.engine.scenario.battery;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** Scenario 4: never lets the battery run flat. */
public final class BatteryMonitorScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "BatteryMonitor";

    @Override
    public String name() {
        return NAME;
    }

    /** Active from the start: the meta-rule generates these at once. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new BatteryMonitor());
    }
}
