package org.proactiverobotics.engine;

/**
 * A condition-action rule of the Proactive Engine, in five parts that the engine runs in this
 * order: data acquisition, activation guards, conditions, actions, rules generation.
 *
 * <p>A rule runs once per iteration. To keep running it regenerates itself in
 * {@link #rulesGeneration} ({@code ctx.generate(this)}); a rule that is not regenerated is gone.
 *
 * <p>State: the rule's non-transient fields are its persisted state (saved as JSON with Gson at
 * the end of every iteration); data acquired during an iteration belongs in {@code transient}
 * fields. Give every rule a no-argument constructor (it may be private) so that field
 * initialisers run when it is loaded back, and make it a top-level or static nested class.
 * Never keep services (DAOs, connections) in fields: ask {@link RuleContext#service} for them.
 *
 * <p>Every part may throw; the engine records the failure and the rule generates nothing.
 */
public abstract class Rule {

    /** @return the name of the scenario this rule belongs to */
    public abstract String scenario();

    /** @return this rule's name in traces and failure records; the simple class name by default */
    public String name() {
        return getClass().getSimpleName();
    }

    /**
     * Part 1a: acquires the data the activation guards need. Both algorithms run it first.
     *
     * @param ctx the engine context
     */
    protected void acquireGuardData(RuleContext ctx) throws Exception {
    }

    /**
     * Part 1b: acquires the data only the conditions and actions need. The standard algorithm
     * runs it right after {@link #acquireGuardData}; the lazy one only once the guards held.
     *
     * @param ctx the engine context
     */
    protected void acquireConditionData(RuleContext ctx) throws Exception {
    }

    /**
     * Part 2: whether the rule is activated; false skips the conditions and the actions.
     *
     * @param ctx the engine context
     * @return true to go on to the conditions
     */
    protected boolean activationGuards(RuleContext ctx) throws Exception {
        return true;
    }

    /**
     * Part 3: whether the actions run; false skips them.
     *
     * @param ctx the engine context
     * @return true to run the actions
     */
    protected boolean conditions(RuleContext ctx) throws Exception {
        return true;
    }

    /**
     * Part 4: what the rule does.
     *
     * @param ctx the engine context
     */
    protected void actions(RuleContext ctx) throws Exception {
    }

    /**
     * Part 5: creates the rules of the next iteration with {@link RuleContext#generate}, this
     * very rule included to keep it running. Always runs, whatever the guards and conditions
     * gave, unless an earlier part threw.
     *
     * @param ctx     the engine context
     * @param outcome whether the guards and the conditions held
     */
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) throws Exception {
    }

    @Override
    public String toString() {
        return scenario() + "/" + name();
    }
}
