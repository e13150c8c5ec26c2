package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** docs/engine.md, the five parts: the five parts, their order, the skipping, rules generation always running. */
class RulePartsTest {

    private final Log log = new Log();

    private ProactiveEngine engine(Algorithm algorithm, Rule... rules) {
        ProactiveEngine engine = ProactiveEngine.builder().algorithm(algorithm).service(Log.class, log).build();
        engine.startFresh(rules);
        return engine;
    }

    @Test
    void standardAlgorithmRunsTheFivePartsInOrder() {
        engine(Algorithm.STANDARD, Probe.once("r")).runIteration();
        assertThat(log.take()).containsExactly("r:guardData", "r:conditionData", "r:guards", "r:conditions", "r:actions",
                "r:generation ACTIONS_RUN");
    }

    @Test
    void lazyAlgorithmAcquiresConditionDataAfterTheGuards() {
        engine(Algorithm.LAZY, Probe.once("r")).runIteration();
        assertThat(log.take()).containsExactly("r:guardData", "r:guards", "r:conditionData", "r:conditions", "r:actions",
                "r:generation ACTIONS_RUN");
    }

    @Test
    void falseGuardsSkipConditionsAndActionsButNotRulesGeneration() {
        engine(Algorithm.STANDARD, Probe.once("r").guards(false)).runIteration();
        assertThat(log.take()).containsExactly("r:guardData", "r:conditionData", "r:guards", "r:generation NOT_ACTIVATED");
    }

    @Test
    void falseConditionsSkipActionsButNotRulesGeneration() {
        engine(Algorithm.STANDARD, Probe.once("r").conditions(false)).runIteration();
        assertThat(log.take()).containsExactly("r:guardData", "r:conditionData", "r:guards", "r:conditions",
                "r:generation CONDITIONS_FALSE");
    }

    @Test
    void rulesGenerationAlwaysRunsAndSeesWhatGuardsAndConditionsGave() {
        engine(Algorithm.LAZY, Probe.once("a").guards(false), Probe.once("b").conditions(false), Probe.once("c")).runIteration();
        assertThat(log.take()).filteredOn(e -> e.contains("generation"))
                .containsExactly("a:generation NOT_ACTIVATED", "b:generation CONDITIONS_FALSE", "c:generation ACTIONS_RUN");
        assertThat(Outcome.NOT_ACTIVATED.guardsHeld()).isFalse();
        assertThat(Outcome.CONDITIONS_FALSE.guardsHeld()).isTrue();
        assertThat(Outcome.CONDITIONS_FALSE.conditionsHeld()).isFalse();
        assertThat(Outcome.ACTIONS_RUN.conditionsHeld()).isTrue();
    }

    @Test
    void aRuleThatClonesItselfRunsAgainWithItsStateKept() {
        Probe probe = new Probe("r", 2);
        ProactiveEngine engine = engine(Algorithm.STANDARD, probe);
        engine.runIteration();
        engine.runIteration();
        assertThat(engine.nextQueue()).containsExactly(probe);
        engine.runIteration();
        assertThat(probe.runs).isEqualTo(3);
        assertThat(engine.nextQueue()).as("a rule not regenerated is gone").isEmpty();
        assertThat(engine.runIteration().rulesRun()).isZero();
    }

    @Test
    void aRuleRunsOncePerIterationEvenWhenGeneratedDuringIt() {
        ProactiveEngine engine = engine(Algorithm.STANDARD, Probe.forever("r"));
        for (int i = 0; i < 3; i++) {
            assertThat(engine.runIteration().rulesRun()).isEqualTo(1);
        }
        assertThat(log.take()).filteredOn(e -> e.endsWith("actions")).hasSize(3);
    }
}
