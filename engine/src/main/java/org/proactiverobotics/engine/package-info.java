/**
 * The Proactive Engine core: {@link org.proactiverobotics.engine.Rule}, the engine's
 * {@code currentQueue} and {@code nextQueue}, scenarios and their meta-rules, the shared memory
 * (CommandArray, PriorityArray) and what the saved state is
 * ({@link org.proactiverobotics.engine.StateStore}, {@link org.proactiverobotics.engine.SavedState}).
 * It is the bottom layer: it imports none of the engine's other packages and no database code;
 * saving over JDBC is {@code org.proactiverobotics.engine.persistence}, beside it.
 *
 * <p>A scenario lives in a package of its own and imports only this one:
 * <pre>{@code
 * public final class BatteryMonitor extends Rule {          // a rule: fields = saved state
 *     private double thresholdPct = 20;
 *     private transient double levelPct;                   // acquired data: not saved
 *     private BatteryMonitor() { }                         // for Gson
 *     public String scenario() { return "BatteryMonitor"; }
 *     protected void acquireGuardData(RuleContext ctx) throws Exception {
 *         levelPct = ctx.service(BatteryDao.class).newestLevelPct(ctx.robotId());
 *     }
 *     protected boolean activationGuards(RuleContext ctx) { return levelPct < thresholdPct; }
 *     protected void actions(RuleContext ctx) {
 *         ctx.suggest("RECHARGE");                         // into the scenario's CommandArray slot
 *     }
 *     protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
 *         ctx.generate(outcome.conditionsHeld() ? new MoveToRecharge() : this);   // clone or hand over
 *     }
 * }
 *
 * public final class BatteryScenario implements Scenario {  // listed in META-INF/services/org.proactiverobotics.engine.Scenario
 *     public String name() { return "BatteryMonitor"; }
 *     public List<Rule> firstRules() { return List.of(new BatteryMonitor()); }  // started by StartScenario
 * }
 * }</pre>
 *
 * <p>A scenario that should wait for a context overrides {@code metaRule()} with a
 * {@link org.proactiverobotics.engine.MetaRule} whose guards and conditions decide when.
 */
package org.proactiverobotics.engine;
