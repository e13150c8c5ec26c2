package org.proactiverobotics.engine.testscenarios;

import org.proactiverobotics.engine.RuleContext;

/** Notes which rules ran, in the shared memory (a test aid). */
public final class Ran {

    /** The key of the shared memory value holding the notes. */
    public static final String KEY = "ran";

    private Ran() {
    }

    static void note(RuleContext ctx, String what) {
        ctx.memory().values().merge(KEY, ctx.iteration() + ":" + what, (a, b) -> a + " " + b);
    }
}
