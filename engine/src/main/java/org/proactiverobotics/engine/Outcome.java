package org.proactiverobotics.engine;

/** How far a rule got in one run: what its activation guards and conditions gave, or that a part threw. */
public enum Outcome {
    /** The activation guards were false: conditions and actions were skipped. */
    NOT_ACTIVATED(false, false),
    /** The guards held, the conditions were false: actions were skipped. */
    CONDITIONS_FALSE(true, false),
    /** Guards and conditions held and the actions ran. */
    ACTIONS_RUN(true, true),
    /** A part threw (see the {@link RuleFailure}); rules generation never sees this value. */
    FAILED(false, false);

    private final boolean guardsHeld;
    private final boolean conditionsHeld;

    Outcome(boolean guardsHeld, boolean conditionsHeld) {
        this.guardsHeld = guardsHeld;
        this.conditionsHeld = conditionsHeld;
    }

    /** @return true when the activation guards held */
    public boolean guardsHeld() {
        return guardsHeld;
    }

    /** @return true when the guards and the conditions held (so the actions ran) */
    public boolean conditionsHeld() {
        return conditionsHeld;
    }
}
