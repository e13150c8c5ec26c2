package org.proactiverobotics.engine.scenario.destination;

import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;

/** Scenario 2: moves the robot to its checkpoints, in order. */
public final class ReachDestinationScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "ReachDestination";
    /** Its default index in the CommandArray. */
    public static final int SLOT = 0;

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public MetaRule metaRule() {
        return new Start();
    }

    /** Starts GetCheckpoint. */
    public static final class Start extends MetaRule {
        @Override
        public String scenario() {
            return NAME;
        }

        @Override
        protected void generateScenarioRules(RuleContext ctx) {
            ctx.generate(new GetCheckpoint());
        }
    }
}
