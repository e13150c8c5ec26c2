package org.proactiverobotics.engine;

import java.util.List;

/**
 * The first rule: its rules generation creates the meta-rule of every configured scenario, in
 * the configured order (the paper's 1 → 4 → 2 → 3 → 5), which generation order then keeps in
 * every iteration. Scenarios are looked up by name in the engine's {@link ScenarioRegistry}
 * service, or with ServiceLoader when none is registered. StartUp runs once.
 */
public final class StartUp extends Rule {

    /** The scenario name StartUp reports. */
    public static final String SCENARIO = "StartUp";

    private List<String> scenarios;

    private StartUp() {
        this.scenarios = List.of();
    }

    /** @param scenarios the scenario names, in start order */
    public StartUp(List<String> scenarios) {
        this.scenarios = List.copyOf(scenarios);
    }

    /** @return the scenario names, in start order */
    public List<String> scenarios() {
        return List.copyOf(scenarios);
    }

    @Override
    public String scenario() {
        return SCENARIO;
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ScenarioRegistry registry = ctx.findService(ScenarioRegistry.class).orElseGet(ScenarioRegistry::load);
        // Every name is resolved before any rule is generated: an unknown one fails StartUp whole.
        scenarios.forEach(registry::get);
        for (String name : scenarios) {
            MetaRule meta;
            try {
                meta = registry.metaRule(name);
            } catch (RuntimeException | LinkageError e) {
                // One scenario's broken metaRule() must not keep the others from starting.
                meta = new FailedStart(name, "its metaRule() threw " + e);
            }
            ctx.generate(meta);
        }
    }
}
