package org.proactiverobotics.engine;

/**
 * The rule that starts a scenario. Its activation guards and conditions decide from context
 * when the scenario is active (by default at once); then its rules generation creates the
 * scenario's first rules, which keep themselves running by cloning. Until then the meta-rule
 * clones itself to look again in the next iteration.
 */
public abstract class MetaRule extends Rule {

    /**
     * Generates the scenario's first rules with {@link RuleContext#generate}; called when the
     * guards and the conditions held.
     *
     * @param ctx the engine context
     */
    protected abstract void generateScenarioRules(RuleContext ctx) throws Exception;

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) throws Exception {
        if (outcome.conditionsHeld()) {
            generateScenarioRules(ctx);
        } else {
            ctx.generate(this);
        }
    }
}
