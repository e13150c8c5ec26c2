package org.proactiverobotics.engine.testscenarios;

import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;

/** A test scenario found by ServiceLoader; active from iteration 3. */
public final class Beta implements Scenario {

    @Override
    public String name() {
        return "Beta";
    }

    @Override
    public MetaRule metaRule() {
        return new Meta();
    }

    /** Starts Beta's Tick from iteration 3. */
    public static final class Meta extends MetaRule {
        @Override
        public String scenario() {
            return "Beta";
        }

        @Override
        protected boolean activationGuards(RuleContext ctx) {
            Ran.note(ctx, "Beta/Meta");
            return ctx.iteration() >= 3;
        }

        @Override
        protected void generateScenarioRules(RuleContext ctx) {
            ctx.generate(new Tick("Beta"));
        }
    }
}
