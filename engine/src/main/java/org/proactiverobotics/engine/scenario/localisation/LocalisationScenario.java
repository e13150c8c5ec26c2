package org.proactiverobotics.engine.scenario.localisation;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/**
 * Keeps the engine's estimate of where the robot is ({@code pose_estimate}) from its wheel
 * odometry, its inertial unit, its GPS when it has one and its distance scan matched against the
 * engine's own map when it has none. Every scenario that needs the robot's pose reads that
 * estimate. Suggests nothing.
 */
public final class LocalisationScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "Localisation";

    @Override
    public String name() {
        return NAME;
    }

    /** Kept for the whole mission: a lost estimator is restored by the fail-safe. */
    @Override
    public boolean keepsFirstRules() {
        return true;
    }

    /** Active from the start. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new EstimatePose());
    }
}
