package org.proactiverobotics.engine;

/**
 * The default meta-rule of a {@link Scenario}: active at once, it generates the scenario's
 * {@link Scenario#firstRules()}, which keep themselves running by cloning. It holds only the
 * scenario's name (so it is saved and resumed like any rule) and finds the scenario the way
 * {@link StartUp} does: the engine's {@link ScenarioRegistry} service, else ServiceLoader.
 */
public final class StartScenario extends MetaRule {

    private String scenario;

    private StartScenario() {
    }

    /** @param scenario the name of the scenario to start */
    public StartScenario(String scenario) {
        this.scenario = scenario;
    }

    @Override
    public String scenario() {
        return scenario;
    }

    @Override
    public String name() {
        return "StartScenario(" + scenario + ")";
    }

    @Override
    protected void generateScenarioRules(RuleContext ctx) {
        ScenarioRegistry registry = ctx.findService(ScenarioRegistry.class).orElseGet(ScenarioRegistry::load);
        for (Rule rule : registry.get(scenario).firstRules()) {
            ctx.generate(rule);
        }
    }
}
