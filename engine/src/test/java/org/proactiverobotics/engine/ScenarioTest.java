package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.testscenarios.Alpha;
import org.proactiverobotics.engine.testscenarios.Beta;
import org.proactiverobotics.engine.testscenarios.Gamma;
import org.proactiverobotics.engine.testscenarios.Ran;

/** Scenarios found by ServiceLoader, StartUp creating their meta-rules in the configured order, MetaRule. */
class ScenarioTest {

    private String ran(ProactiveEngine engine) {
        String notes = engine.memory().values().remove(Ran.KEY);
        return notes == null ? "" : notes;
    }

    @Test
    void serviceLoaderFindsTheScenariosWithoutEngineCode() {
        // other scenarios (the robot's) may be on the class path too
        assertThat(ScenarioRegistry.load().names()).contains("Alpha", "Beta", "Gamma");
    }

    @Test
    void startUpCreatesTheMetaRulesInTheConfiguredOrderAndTheOrderHolds() {
        ProactiveEngine engine = ProactiveEngine.builder().build();
        engine.startFresh(ScenarioRegistry.load().startUp(List.of("Gamma", "Alpha", "Beta")));
        engine.runIteration();
        assertThat(engine.nextQueue()).extracting(Rule::scenario).containsExactly("Gamma", "Alpha", "Beta");
        assertThat(engine.nextQueue()).allMatch(r -> r instanceof MetaRule);
        engine.runIteration();
        assertThat(ran(engine)).isEqualTo("2:Gamma/Meta 2:Alpha/Meta 2:Beta/Meta");
        engine.runIteration();
        assertThat(ran(engine)).as("Beta's meta-rule cloned itself until active")
                .isEqualTo("3:Gamma/Tick 3:Alpha/Tick 3:Beta/Meta");
        engine.runIteration();
        assertThat(ran(engine)).isEqualTo("4:Gamma/Tick 4:Alpha/Tick 4:Beta/Tick");
    }

    @Test
    void anUnknownScenarioIsAClearErrorListingTheKnownOnes() {
        ScenarioRegistry registry = ScenarioRegistry.of(new Gamma(), new Beta(), new Alpha());
        assertThatThrownBy(() -> registry.startUp(List.of("Alpha", "Nope")))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("unknown scenario 'Nope'; known scenarios: [Alpha, Beta, Gamma]");
        assertThatThrownBy(() -> ScenarioRegistry.load().get("Nope")).hasMessageContaining("known scenarios: [Alpha, ");

        ProactiveEngine engine = ProactiveEngine.builder().service(ScenarioRegistry.class, registry).build();
        engine.startFresh(new StartUp(List.of("Alpha", "Nope")));
        IterationSummary summary = engine.runIteration();
        assertThat(summary.rulesFailed()).isEqualTo(1);
        assertThat(engine.nextQueue()).as("StartUp failed whole: not even Alpha started").isEmpty();
        assertThat(engine.lastIterationFailures().get(0).message())
                .contains("unknown scenario 'Nope'; known scenarios: [Alpha, Beta, Gamma]");
        assertThat(engine.lastIterationFailures().get(0).scenario()).isEqualTo(StartUp.SCENARIO);
    }

    @Test
    void aRegistryServiceReplacesTheServiceLoader() {
        ProactiveEngine engine = ProactiveEngine.builder()
                .service(ScenarioRegistry.class, ScenarioRegistry.of(new Gamma(), new Alpha())).build();
        engine.startFresh(new StartUp(List.of("Alpha", "Gamma")));
        engine.runIteration();
        assertThat(engine.nextQueue()).extracting(Rule::scenario).containsExactly("Alpha", "Gamma");
        engine.startFresh(new StartUp(List.of("Beta")));
        engine.runIteration();
        assertThat(engine.lastIterationFailures().get(0).message()).contains("known scenarios: [Alpha, Gamma]");
    }

    @Test
    void twoScenariosOfOneNameAreRefused() {
        assertThatThrownBy(() -> ScenarioRegistry.of(new Alpha(), new Alpha()))
                .hasMessageContaining("two scenarios are named 'Alpha'");
    }
}
