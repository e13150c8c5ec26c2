package org.proactiverobotics.engine.scenario.battery;

import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;

/** Scenario 4: never lets the battery run flat. */
public final class BatteryMonitorScenario implements Scenario {

    /** The scenario's name in configuration and records. */
    public static final String NAME = "BatteryMonitor";
    /** Its default index in the CommandArray. */
    public static final int SLOT = 1;

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public MetaRule metaRule() {
        return new Start();
    }

    /** Starts BatteryMonitor. */
    public static final class Start extends MetaRule {
        @Override
        public String scenario() {
            return NAME;
        }

        @Override
        protected void generateScenarioRules(RuleContext ctx) {
            ctx.generate(new BatteryMonitor());
        }
    }
}
