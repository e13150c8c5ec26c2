package org.proactiverobotics.engine.scenario.failsafe;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.MetaRule;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.RuleFailure;
import org.proactiverobotics.engine.Scenario;
import org.proactiverobotics.engine.ScenarioRegistry;
import org.proactiverobotics.engine.StartUp;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The fail-safe rule. Each iteration in which a rule failed (this one's failures so far and the
 * previous one's, {@link RuleContext#failures()}):
 * <ol>
 *   <li>every CommandArray slot holding a suggestion of a failed scenario is cleared, so the
 *       decision that follows cannot pick it (the engine already dropped what the failed rule
 *       generated);</li>
 *   <li>a failed scenario with no rule left ({@link RuleContext#scheduled}: a failed rule is not
 *       regenerated) is stood in for by STOP, entered as this scenario's suggestion in the gone
 *       scenario's slot (the one the engine gave it), so the strategy still decides: under
 *       safety-first a dead obstacle avoidance stops the robot rather than let it drive blind.
 *       A scenario without a slot (data acquisition, the decision itself) gets its STOP in the
 *       top-priority slot and, once, sent straight to engine_comments, because without it the
 *       rest decide on stale data or nobody decides at all;</li>
 *   <li>a gone scenario is restarted from its meta-rule ({@link ScenarioRegistry}) after
 *       {@value #RESTART_AFTER_ITERATIONS} iterations, the delay doubling with each restart of
 *       the same episode up to {@value #MAX_RESTART_DELAY_ITERATIONS}, so that one transient
 *       database error does not cost obstacle avoidance for the rest of the mission and one that
 *       lasts does not cost a restart every few iterations. STOP stands in until the restarted
 *       scenario runs its own rules. The meta-rule is generated before this rule (or after it,
 *       for a scenario that ran after it, like the decision), so the order of StartUp holds.</li>
 * </ol>
 * What it does is logged once per step of an episode (failing, gone, restarted, back), and
 * recorded in the shared memory, saved with the engine state every iteration, under
 * {@code "FailSafe.<scenario>"}; the failures themselves are in rule_failures. An episode ends
 * when the scenario is running and has not failed for two iterations. A scenario that lost one
 * rule of several (data acquisition losing GetDS) still has rules, so it is not restarted
 * (restarting would run the others twice); its failure is recorded.
 *
 * <p>This rule does no I/O it cannot do without: it sends STOP for a gone scenario without a
 * slot (logged when that fails); that failing never makes this rule fail.
 */
public final class WatchFailures extends Rule {

    /** Iterations a gone scenario waits before its first restart. */
    public static final long RESTART_AFTER_ITERATIONS = 16;
    /** The longest wait between restarts, iterations. */
    public static final long MAX_RESTART_DELAY_ITERATIONS = 1024;
    /** The shared-memory key prefix of the records: {@code "FailSafe.ObstacleAvoidance"}. */
    public static final String RECORD_PREFIX = FailSafeScenario.NAME + ".";

    private static final Logger LOG = LoggerFactory.getLogger(WatchFailures.class);
    private static final String STOP = org.proactiverobotics.engine.motion.Steering.STOP;

    /** The scenarios in trouble, by name. */
    private TreeMap<String, Episode> episodes = new TreeMap<>();

    private transient List<RuleFailure> failures = List.of();
    private transient List<MetaRule> restartBefore = new ArrayList<>();
    private transient List<MetaRule> restartAfter = new ArrayList<>();
    private transient List<Rule> restored = new ArrayList<>();

    /** A watch with nothing seen yet. */
    public WatchFailures() {
    }

    @Override
    public String scenario() {
        return FailSafeScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        failures = ctx.failures();
        restartBefore.clear();
        restartAfter.clear();
        restored.clear();
    }

    /** Guard: something failed lately, or a scenario is still in trouble (the quiet path does nothing). */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return !failures.isEmpty() || !episodes.isEmpty();
    }

    @Override
    protected void actions(RuleContext ctx) {
        long iteration = ctx.iteration();
        for (RuleFailure f : failures) {
            if (!FailSafeScenario.NAME.equals(f.scenario()) && !StartUp.SCENARIO.equals(f.scenario())) {
                failed(ctx, f, iteration);
            }
        }
        Iterator<Map.Entry<String, Episode>> it = episodes.entrySet().iterator();
        while (it.hasNext()) {
            Map.Entry<String, Episode> entry = it.next();
            if (follow(ctx, entry.getKey(), entry.getValue(), iteration)) {
                it.remove();
            }
        }
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        restored.forEach(ctx::generate);
        restartBefore.forEach(ctx::generate);
        ctx.generate(this);
        restartAfter.forEach(ctx::generate);
    }

    /** A failure: the scenario's suggestions go, and its episode starts or goes on. */
    private void failed(RuleContext ctx, RuleFailure f, long iteration) {
        String scenario = f.scenario();
        CommandArray commands = ctx.memory().commandArray();
        for (int slot = 0; slot < commands.size(); slot++) {
            Suggestion s = commands.get(slot);
            if (s != null && s.scenario().equals(scenario)) {
                commands.clear(slot);
            }
        }
        Episode episode = episodes.get(scenario);
        String what = f.rule() + " in " + f.part() + ": " + f.message();
        if (episode == null) {
            // Seen in the iteration it happened: the scenario runs before this rule.
            episode = new Episode(f.iteration(), f.iteration() == iteration);
            episodes.put(scenario, episode);
            LOG.warn("fail-safe: scenario {} failed at iteration {} ({}); its suggestions are withdrawn",
                    scenario, f.iteration(), what);
            record(ctx, scenario, "failing since iteration " + f.iteration() + ": " + what);
        }
        episode.lastFailure = Math.max(episode.lastFailure, f.iteration());
        episode.failure = what;
    }

    /** One iteration of an episode; true when it is over. */
    private boolean follow(RuleContext ctx, String scenario, Episode e, long iteration) {
        boolean queued = ctx.scheduled(scenario);
        if (queued && e.goneSince == 0 && e.restartedAt == 0) {
            restoreLostRules(ctx, scenario, e); // still running, but maybe without one of its rules
        }
        if (!queued) {
            if (e.goneSince == 0) {
                e.goneSince = iteration;
                if (e.restarts == 0) {
                    LOG.warn("fail-safe: scenario {} has no rule left; STOP stands in for it in slot {}", scenario,
                            slotOf(ctx, scenario));
                }
                if (ctx.memory().slotOf(scenario) < 0) {
                    sendStop(ctx, scenario);
                }
            }
            if (e.restartDue == 0) {
                e.restartDue = iteration + Math.min(RESTART_AFTER_ITERATIONS << Math.min(e.restarts, 20),
                        MAX_RESTART_DELAY_ITERATIONS);
                record(ctx, scenario, "gone at iteration " + e.goneSince + " (" + e.failure + "); STOP stands in; restart "
                        + (e.restarts + 1) + " due at iteration " + e.restartDue);
            }
            if (iteration >= e.restartDue) {
                restart(ctx, scenario, e, iteration);
            }
        } else if (e.goneSince != 0 && e.restartedAt != 0 && iteration >= e.restartedAt + 2) {
            e.goneSince = 0; // its meta-rule ran last iteration: its own rules run now
        }
        if (e.standIn()) {
            ctx.memory().commandArray().enter(slotOf(ctx, scenario), STOP, FailSafeScenario.NAME, iteration);
        }
        if (queued && !e.standIn() && iteration - e.lastFailure >= 2) {
            String back = e.restarts > 0 ? "back after " + e.restarts + " restart(s)"
                    : e.restoredRules > 0 ? "running again with " + e.restoredRules + " lost rule(s) restored" : "still running";
            LOG.info("fail-safe: scenario {} {}, no failure since iteration {}", scenario, back, e.lastFailure);
            record(ctx, scenario, back + " at iteration " + iteration + "; failed from iteration " + e.since + " to "
                    + e.lastFailure + " (last: " + e.failure + ")");
            return true;
        }
        return false;
    }

    /** A scenario that keeps its first rules gets back any a failure took away (a lost GetDS would freeze the scan). */
    private void restoreLostRules(RuleContext ctx, String scenario, Episode e) {
        Scenario definition;
        try {
            definition = ctx.findService(ScenarioRegistry.class).orElseGet(ScenarioRegistry::load).get(scenario);
        } catch (RuntimeException ex) {
            return; // not a registered scenario: nothing to restore from
        }
        if (!definition.keepsFirstRules()) {
            return;
        }
        for (Rule rule : definition.firstRules()) {
            if (!ctx.scheduled(scenario, rule.name())) {
                restored.add(rule);
                if (e.restoredRules++ == 0) {
                    LOG.warn("fail-safe: {} of scenario {} was lost ({}); restored", rule.name(), scenario, e.failure);
                }
                record(ctx, scenario, rule.name() + " restored at iteration " + ctx.iteration() + " (" + e.failure + ")");
            }
        }
    }

    private void restart(RuleContext ctx, String scenario, Episode e, long iteration) {
        MetaRule meta;
        try {
            ScenarioRegistry registry = ctx.findService(ScenarioRegistry.class).orElseGet(ScenarioRegistry::load);
            meta = registry.get(scenario).metaRule();
        } catch (RuntimeException ex) {
            e.restartDue = Long.MAX_VALUE; // cannot be restarted: STOP stands in for good
            LOG.warn("fail-safe: scenario {} cannot be restarted ({}); STOP stands in for it for good", scenario,
                    ex.getMessage());
            record(ctx, scenario, "gone at iteration " + e.goneSince + " and cannot be restarted: " + ex.getMessage());
            return;
        }
        (e.before ? restartBefore : restartAfter).add(meta);
        e.restarts++;
        e.restartedAt = iteration;
        e.restartDue = 0;
        LOG.info("fail-safe: scenario {} restarted at iteration {} (restart {} of this episode)", scenario, iteration,
                e.restarts);
        record(ctx, scenario, "restarted at iteration " + iteration + " (restart " + e.restarts + "; gone since "
                + e.goneSince + ": " + e.failure + ")");
    }

    /** The scenario's slot, or the top-priority one when it has none. */
    private int slotOf(RuleContext ctx, String scenario) {
        int slot = ctx.memory().slotOf(scenario);
        if (slot >= 0 && slot < ctx.memory().commandArray().size()) {
            return slot;
        }
        return ctx.memory().priorityArray().slotsByPriority()[0];
    }

    /** Without a slot, a gone scenario may be the decision itself: tell the robot directly. */
    private static void sendStop(RuleContext ctx, String scenario) {
        try {
            long simTimeMs = Math.max(0, ctx.service(SensorReadings.class).robotClockMs());
            ctx.service(EngineComments.class).send(ctx.iteration(), simTimeMs, FailSafeScenario.NAME, STOP);
        } catch (RuntimeException e) {
            LOG.warn("fail-safe: could not send STOP for gone scenario {}: {}", scenario, e.getMessage());
        }
    }

    private static void record(RuleContext ctx, String scenario, String text) {
        ctx.memory().values().put(RECORD_PREFIX + scenario, text);
    }
}
