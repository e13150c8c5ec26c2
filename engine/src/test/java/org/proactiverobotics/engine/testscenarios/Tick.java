package org.proactiverobotics.engine.testscenarios;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;

/** A scenario's rule: notes "scenario/Tick" in the shared memory's "ran" value each iteration and clones itself. */
public final class Tick extends Rule {

    private String scenario;

    private Tick() {
    }

    Tick(String scenario) {
        this.scenario = scenario;
    }

    @Override
    public String scenario() {
        return scenario;
    }

    @Override
    protected void actions(RuleContext ctx) {
        Ran.note(ctx, scenario + "/Tick");
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }
}
