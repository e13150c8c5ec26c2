package org.proactiverobotics.engine;

/**
 * Observes the engine: each rule's trace, each failure, each iteration's summary. Called on the
 * engine thread; keep it quick. When no listener is registered no trace is built at all.
 */
public interface IterationListener {

    /**
     * Called after nextQueue moved into currentQueue, before the first rule runs.
     *
     * @param iteration the iteration starting
     * @param queued    the number of rules in currentQueue
     */
    default void iterationStarted(long iteration, int queued) {
    }

    /** Called after each rule ran. */
    default void ruleRan(RuleTrace trace) {
    }

    /** Called when a part of a rule threw, before {@link #ruleRan}. */
    default void ruleFailed(RuleFailure failure) {
    }

    /** Called at the end of an iteration, after the state was saved. */
    default void iterationEnded(IterationSummary summary) {
    }
}
