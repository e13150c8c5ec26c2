package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** A scenario whose metaRule() throws fails in its own name at its start; the others start as usual. */
class FailedStartTest {

    /** A scenario whose meta-rule cannot be made. */
    static final class Broken implements Scenario {
        @Override
        public String name() {
            return "Broken";
        }

        @Override
        public MetaRule metaRule() {
            throw new IllegalStateException("no meta-rule today");
        }
    }

    /** A scenario starting one probe. */
    static final class Fine implements Scenario {
        @Override
        public String name() {
            return "Fine";
        }

        @Override
        public List<Rule> firstRules() {
            return List.of(Probe.forever("fine"));
        }
    }

    @Test
    void aThrowingMetaRuleIsARecordedFailureOfItsScenarioAndTheOthersRun() {
        ProactiveEngine engine = ProactiveEngine.builder()
                .service(ScenarioRegistry.class, ScenarioRegistry.of(new Broken(), new Fine())).build();
        engine.start(new StartUp(List.of("Broken", "Fine")));
        engine.runIteration(); // StartUp
        engine.runIteration(); // meta-rules: Broken's stand-in fails, Fine's starts its probe
        assertThat(engine.lastIterationFailures()).singleElement().satisfies(f -> {
            assertThat(f.scenario()).isEqualTo("Broken");
            assertThat(f.message()).contains("scenario Broken could not start").contains("no meta-rule today");
        });
        engine.runIteration();
        assertThat(engine.nextQueue()).extracting(Rule::name).containsExactly("fine");
        assertThat(engine.lastIterationFailures()).isEmpty();
    }

    /** A rule that throws an Error short of the JVM failing: a plug-in's fault. */
    static final class ThrowsError extends Rule {
        @Override
        public String scenario() {
            return "Plugin";
        }

        @Override
        protected void actions(RuleContext ctx) {
            throw new NoClassDefFoundError("com/example/Missing");
        }
    }

    @Test
    void aLinkageErrorOrStackOverflowInAPartIsARuleFailure() {
        ProactiveEngine engine = ProactiveEngine.builder().build();
        engine.start(new ThrowsError(), Probe.forever("p"));
        IterationSummary summary = engine.runIteration();
        assertThat(summary.rulesFailed()).isEqualTo(1);
        assertThat(engine.lastIterationFailures().get(0).message()).contains("NoClassDefFoundError");
        assertThat(engine.nextQueue()).extracting(Rule::name).containsExactly("p");
    }
}
