package org.proactiverobotics.engine;

/** A test rule that throws in one part, after generating a child when that part is rules generation. */
final class Thrower extends Rule {

    Part part;

    private Thrower() {
    }

    Thrower(Part part) {
        this.part = part;
    }

    @Override
    public String scenario() {
        return "failing";
    }

    private void maybeThrow(Part here) {
        if (here == part) {
            throw new IllegalStateException("boom in " + here);
        }
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        maybeThrow(Part.GUARD_DATA_ACQUISITION);
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        maybeThrow(Part.CONDITION_DATA_ACQUISITION);
    }

    @Override
    protected boolean activationGuards(RuleContext ctx) {
        maybeThrow(Part.ACTIVATION_GUARDS);
        return true;
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        maybeThrow(Part.CONDITIONS);
        return true;
    }

    @Override
    protected void actions(RuleContext ctx) {
        maybeThrow(Part.ACTIONS);
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(Probe.once("child-of-thrower"));
        ctx.generate(this);
        maybeThrow(Part.RULES_GENERATION);
    }
}
