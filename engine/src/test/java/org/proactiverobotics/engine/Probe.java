package org.proactiverobotics.engine;

/**
 * A test rule that logs every part it runs as "id:PART", with configurable guards and conditions
 * and a number of clones (-1: forever).
 */
final class Probe extends Rule {

    String id;
    boolean guards = true;
    boolean conditions = true;
    int clones;
    int runs;

    private Probe() {
    }

    Probe(String id, int clones) {
        this.id = id;
        this.clones = clones;
    }

    static Probe forever(String id) {
        return new Probe(id, -1);
    }

    static Probe once(String id) {
        return new Probe(id, 0);
    }

    Probe guards(boolean value) {
        guards = value;
        return this;
    }

    Probe conditions(boolean value) {
        conditions = value;
        return this;
    }

    @Override
    public String scenario() {
        return "test";
    }

    @Override
    public String name() {
        return id;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        log(ctx, "guardData");
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        log(ctx, "conditionData");
    }

    @Override
    protected boolean activationGuards(RuleContext ctx) {
        log(ctx, "guards");
        return guards;
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        log(ctx, "conditions");
        return conditions;
    }

    @Override
    protected void actions(RuleContext ctx) {
        log(ctx, "actions");
        runs++;
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        log(ctx, "generation " + outcome);
        if (clones != 0) {
            if (clones > 0) {
                clones--;
            }
            ctx.generate(this);
        }
    }

    private void log(RuleContext ctx, String part) {
        ctx.findService(Log.class).ifPresent(l -> l.add(id + ":" + part));
    }
}
