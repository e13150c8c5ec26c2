package org.proactiverobotics.bench.engine;

import org.openjdk.jmh.annotations.AuxCounters;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/** Counts rules executed, so JMH reports rules per second (the "rules" line) beside iterations per second. */
@State(Scope.Thread)
@AuxCounters(AuxCounters.Type.OPERATIONS)
public class RuleCounter {

    /** Rules executed in the current measurement iteration. */
    public long rules;

    /** Starts each JMH iteration from zero. */
    @Setup(Level.Iteration)
    public void reset() {
        rules = 0;
    }
}
