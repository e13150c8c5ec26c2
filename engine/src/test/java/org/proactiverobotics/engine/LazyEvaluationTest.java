package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Zampunieris 2008: the lazy algorithm reads condition data only for activated rules. */
class LazyEvaluationTest {

    /** Counts its data reads in a service; activated every third iteration. */
    static final class Reader extends Rule {
        @Override
        public String scenario() {
            return "test";
        }

        @Override
        protected void acquireGuardData(RuleContext ctx) {
            ctx.service(Counts.class).guardReads++;
        }

        @Override
        protected void acquireConditionData(RuleContext ctx) {
            ctx.service(Counts.class).conditionReads++;
        }

        @Override
        protected boolean activationGuards(RuleContext ctx) {
            return ctx.iteration() % 3 == 0;
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }

    static final class Counts {
        int guardReads;
        int conditionReads;
    }

    private Counts run(Algorithm algorithm) {
        Counts counts = new Counts();
        ProactiveEngine engine = ProactiveEngine.builder().algorithm(algorithm).service(Counts.class, counts).build();
        engine.startFresh(new Reader(), new Reader());
        for (int i = 0; i < 9; i++) {
            engine.runIteration();
        }
        return counts;
    }

    @Test
    void standardReadsEverythingForEveryRule() {
        Counts counts = run(Algorithm.STANDARD);
        assertThat(counts.guardReads).isEqualTo(18);
        assertThat(counts.conditionReads).isEqualTo(18);
    }

    @Test
    void lazyReadsConditionDataOnlyWhenTheGuardsHeld() {
        Counts counts = run(Algorithm.LAZY);
        assertThat(counts.guardReads).isEqualTo(18);
        assertThat(counts.conditionReads).as("2 rules x iterations 3, 6, 9").isEqualTo(6);
    }
}
