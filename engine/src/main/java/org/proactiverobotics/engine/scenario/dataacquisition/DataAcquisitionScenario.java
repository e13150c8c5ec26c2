package org.proactiverobotics.engine.scenario.dataacquisition;

import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;

/** Scenario 1: keeps the robot's sensor readings fresh. Always active. */
public final class DataAcquisitionScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "DataAcquisition";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public MetaRule metaRule() {
        return new Start();
    }

    /** Starts GetGPS, GetDS, GetIU and GetBattery. */
    public static final class Start extends MetaRule {
        @Override
        public String scenario() {
            return NAME;
        }

        @Override
        protected void generateScenarioRules(RuleContext ctx) {
            ctx.generate(new GetGPS());
            ctx.generate(new GetDS());
            ctx.generate(new GetIU());
            ctx.generate(new GetBattery());
        }
    }
}
