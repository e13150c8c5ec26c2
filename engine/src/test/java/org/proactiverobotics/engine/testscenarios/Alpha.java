package org.proactiverobotics.engine.testscenarios;

import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;

/** A test scenario found by ServiceLoader; active from iteration 1. */
public final class Alpha implements Scenario {

    @Override
    public String name() {
        return "Alpha";
    }

    @Override
    public MetaRule metaRule() {
        return new Meta();
    }

    /** Starts Alpha's Tick from iteration 1. */
    public static final class Meta extends MetaRule {
        @Override
        public String scenario() {
            return "Alpha";
        }

        @Override
        protected boolean activationGuards(RuleContext ctx) {
            Ran.note(ctx, "Alpha/Meta");
            return ctx.iteration() >= 1;
        }

        @Override
        protected void generateScenarioRules(RuleContext ctx) {
            ctx.generate(new Tick("Alpha"));
        }
    }
}
