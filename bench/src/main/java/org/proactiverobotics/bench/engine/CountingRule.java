package org.proactiverobotics.bench.engine;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;

/** The benchmark workload as a Proactive Engine rule that clones itself every iteration. */
public final class CountingRule extends Rule {

    long value;

    @Override
    public String scenario() {
        return "bench";
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return Workload.condition(value);
    }

    @Override
    protected void actions(RuleContext ctx) {
        value = Workload.action(value);
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }

    /** @return n new rules */
    public static Rule[] many(int n) {
        Rule[] rules = new Rule[n];
        for (int i = 0; i < n; i++) {
            rules[i] = new CountingRule();
        }
        return rules;
    }
}
