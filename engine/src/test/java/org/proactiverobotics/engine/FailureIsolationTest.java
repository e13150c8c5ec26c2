package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.Test;

/** docs/engine.md, failures: a part that throws is recorded, the failed rule generates nothing, the iteration goes on. */
class FailureIsolationTest {

    private final Log log = new Log();

    /** Logs the failures it sees through the context, and keeps watching. */
    static final class Watcher extends Rule {
        @Override
        public String scenario() {
            return "failsafe";
        }

        @Override
        protected void actions(RuleContext ctx) {
            ctx.service(Log.class).add("watcher sees " + ctx.failures().stream()
                    .map(f -> f.iteration() + "/" + f.part()).toList());
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }

    @ParameterizedTest
    @EnumSource(Part.class)
    void aThrowingPartIsRecordedTheRuleGeneratesNothingAndTheIterationGoesOn(Part part) {
        List<RuleFailure> heard = new ArrayList<>();
        ProactiveEngine engine = ProactiveEngine.builder().algorithm(Algorithm.LAZY).service(Log.class, log)
                .listener(new IterationListener() {
                    @Override
                    public void ruleFailed(RuleFailure failure) {
                        heard.add(failure);
                    }
                }).build();
        engine.startFresh(Probe.forever("before"), new Thrower(part), Probe.forever("after"), new Watcher());
        IterationSummary summary = engine.runIteration();

        assertThat(summary.rulesRun()).isEqualTo(4);
        assertThat(summary.rulesFailed()).isEqualTo(1);
        assertThat(summary.rulesGenerated()).as("before, after, watcher: the thrower's rules are dropped").isEqualTo(3);
        assertThat(engine.nextQueue()).extracting(Rule::name).containsExactly("before", "after", "Watcher");
        assertThat(log.take()).contains("after:actions", "watcher sees [1/" + part + "]");

        RuleFailure failure = engine.lastIterationFailures().get(0);
        assertThat(failure.iteration()).isEqualTo(1);
        assertThat(failure.rule()).isEqualTo("Thrower");
        assertThat(failure.scenario()).isEqualTo("failing");
        assertThat(failure.part()).isEqualTo(part);
        assertThat(failure.message()).isEqualTo("IllegalStateException: boom in " + part);
        assertThat(failure.cause()).isInstanceOf(IllegalStateException.class);
        assertThat(heard).containsExactly(failure);
    }

    @Test
    void rulesSeeThePreviousIterationsFailuresThenTheyAge() {
        ProactiveEngine engine = ProactiveEngine.builder().service(Log.class, log).build();
        engine.startFresh(new Watcher(), new Thrower(Part.ACTIONS));
        engine.runIteration();
        assertThat(log.take()).containsExactly("watcher sees []");
        engine.runIteration();
        assertThat(log.take()).as("iteration 1's failure, seen in iteration 2").containsExactly("watcher sees [1/ACTIONS]");
        engine.runIteration();
        assertThat(log.take()).containsExactly("watcher sees []");
    }

    @Test
    void anErrorInAListenerDoesNotStopTheRules() {
        ProactiveEngine engine = ProactiveEngine.builder().service(Log.class, log).listener(new IterationListener() {
            @Override
            public void ruleRan(RuleTrace trace) {
                throw new IllegalStateException("broken listener");
            }
        }).build();
        engine.startFresh(Probe.once("a"), Probe.once("b"));
        assertThat(engine.runIteration().rulesRun()).isEqualTo(2);
        assertThat(log.take()).contains("a:actions", "b:actions");
    }
}
