package org.proactiverobotics.engine;

/**
 * Stands in for the meta-rule of a scenario whose {@link Scenario#metaRule()} threw at StartUp:
 * it fails in the scenario's name when it runs, so that the failure is recorded and handled like
 * any rule's (a fail-safe scenario sees it), and the other scenarios start as usual.
 */
final class FailedStart extends MetaRule {

    private String scenario;
    private String problem;

    private FailedStart() {
    }

    FailedStart(String scenario, String problem) {
        this.scenario = scenario;
        this.problem = problem;
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
    protected void acquireGuardData(RuleContext ctx) {
        throw new IllegalStateException("scenario " + scenario + " could not start: " + problem);
    }

    @Override
    protected void generateScenarioRules(RuleContext ctx) {
        // never reached: the guard data acquisition fails
    }
}
