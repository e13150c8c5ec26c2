package org.proactiverobotics.engine.scenario.decision;

import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;

/** Scenario 5: picks, by priority, the suggestion the robot gets. Started last, so it runs last. */
public final class DecisionMakingScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "DecisionMaking";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public MetaRule metaRule() {
        return new Start();
    }

    /** Starts ReadRobotCommands. */
    public static final class Start extends MetaRule {
        @Override
        public String scenario() {
            return NAME;
        }

        @Override
        protected void generateScenarioRules(RuleContext ctx) {
            ctx.generate(new ReadRobotCommands());
        }
    }
}
