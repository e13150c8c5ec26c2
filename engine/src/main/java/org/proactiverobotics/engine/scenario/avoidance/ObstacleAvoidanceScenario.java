package org.proactiverobotics.engine.scenario.avoidance;

import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;

/** Scenario 3: keeps the robot off obstacles and gets it around them. */
public final class ObstacleAvoidanceScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "ObstacleAvoidance";
    /** Its default index in the CommandArray. */
    public static final int SLOT = 2;

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public MetaRule metaRule() {
        return new Start();
    }

    /** Starts AvoidObstacles. */
    public static final class Start extends MetaRule {
        @Override
        public String scenario() {
            return NAME;
        }

        @Override
        protected void generateScenarioRules(RuleContext ctx) {
            ctx.generate(new AvoidObstacles());
        }
    }
}
