package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Observability: traces of each rule and the iteration summary. */
class ListenerTest {

    private final List<RuleTrace> traces = new ArrayList<>();
    private final List<IterationSummary> summaries = new ArrayList<>();
    private final List<String> starts = new ArrayList<>();

    private final IterationListener listener = new IterationListener() {
        @Override
        public void iterationStarted(long iteration, int queued) {
            starts.add(iteration + ":" + queued);
        }

        @Override
        public void ruleRan(RuleTrace trace) {
            traces.add(trace);
        }

        @Override
        public void iterationEnded(IterationSummary summary) {
            summaries.add(summary);
        }
    };

    @Test
    void traceTellsThePartsRunTheOutcomeAndWhatWasGenerated() {
        ProactiveEngine engine = ProactiveEngine.builder().algorithm(Algorithm.LAZY).listener(listener).build();
        Probe clone = new Probe("clone", 1).conditions(false);
        engine.startFresh(Probe.once("off").guards(false), clone, new Thrower(Part.CONDITIONS));
        engine.runIteration();

        assertThat(starts).containsExactly("1:3");
        assertThat(traces).hasSize(3);
        RuleTrace off = traces.get(0);
        assertThat(off.position()).isZero();
        assertThat(off.partsRun()).containsExactly(Part.GUARD_DATA_ACQUISITION, Part.ACTIVATION_GUARDS, Part.RULES_GENERATION);
        assertThat(off.outcome()).isEqualTo(Outcome.NOT_ACTIVATED);
        assertThat(off.generated()).isEmpty();

        RuleTrace cloned = traces.get(1);
        assertThat(cloned.partsRun()).containsExactly(Part.GUARD_DATA_ACQUISITION, Part.ACTIVATION_GUARDS,
                Part.CONDITION_DATA_ACQUISITION, Part.CONDITIONS, Part.RULES_GENERATION);
        assertThat(cloned.outcome()).isEqualTo(Outcome.CONDITIONS_FALSE);
        assertThat(cloned.generated()).containsExactly(clone);

        RuleTrace failed = traces.get(2);
        assertThat(failed.outcome()).isEqualTo(Outcome.FAILED);
        assertThat(failed.failure().part()).isEqualTo(Part.CONDITIONS);
        assertThat(failed.partsRun()).endsWith(Part.CONDITIONS);
        assertThat(failed.generated()).isEmpty();

        IterationSummary summary = summaries.get(0);
        assertThat(summary.iteration()).isEqualTo(1);
        assertThat(summary.rulesRun()).isEqualTo(3);
        assertThat(summary.rulesGenerated()).isEqualTo(1);
        assertThat(summary.rulesFailed()).isEqualTo(1);
        assertThat(summary.nextQueueSize()).isEqualTo(1);
        assertThat(summary.durationNanos()).isPositive().isGreaterThanOrEqualTo(summary.saveNanos());
    }

    @Test
    void standardTraceListsEveryPartInOrder() {
        ProactiveEngine engine = ProactiveEngine.builder().listener(listener).build();
        engine.startFresh(Probe.once("r"));
        engine.runIteration();
        assertThat(traces.get(0).partsRun()).containsExactly(Part.values());
        assertThat(traces.get(0).outcome()).isEqualTo(Outcome.ACTIONS_RUN);
    }
}
