package org.proactiverobotics.engine.scenario.mapping;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/**
 * Builds the robot's occupancy map from what the engine sees (distance scans placed by the GPS
 * and inertial-unit readings) and keeps it in the shared {@code occupancy_map} rows. Suggests
 * nothing.
 */
public final class MappingScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "Mapping";

    @Override
    public String name() {
        return NAME;
    }

    /** Active from the start. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new UpdateMap());
    }
}
