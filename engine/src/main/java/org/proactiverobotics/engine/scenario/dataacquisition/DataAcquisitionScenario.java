package org.proactiverobotics.engine.scenario.dataacquisition;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/** Scenario 1: keeps the robot's sensor readings fresh. Always active. */
public final class DataAcquisitionScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "DataAcquisition";

    @Override
    public String name() {
        return NAME;
    }

    /** Every watch runs for the whole mission: a lost one is restored by the fail-safe. */
    @Override
    public boolean keepsFirstRules() {
        return true;
    }

    /** Active from the start: the meta-rule generates these at once. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new GetGPS(), new GetDS(), new GetIU(), new GetBattery(), new GetOdometry());
    }
}
