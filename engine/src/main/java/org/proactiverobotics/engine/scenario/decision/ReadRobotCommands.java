package org.proactiverobotics.engine.scenario.decision;

import java.util.Arrays;
import java.util.List;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.PriorityArray;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * Each iteration: loads the strategy into the PriorityArray, takes the highest priority, reads
 * the CommandArray at that index, and if it holds a live command generates SendRobotCommand for
 * it; if empty (or expired), tries the next highest. With no live suggestion at all the robot is
 * told to stop. Runs last, so it sees every suggestion of the iteration.
 *
 * <p>Time-outs, as in ROS twist_mux: each slot has one ({@link StrategyTable.Entry#timeoutMs()},
 * simulated milliseconds). A suggestion is live while its age is at most the time-out, and is
 * cleared once it is not; a scenario that enters a new one each iteration is never affected.
 * Age is measured on the robot's clock as the engine sees it ({@link SensorReadings#robotClockMs()}, as the
 * data acquisition does) from the decision that first saw it, i.e. the iteration it was entered in.
 * Time-out 0, the default, keeps the paper's behaviour: the slot is cleared after each decision,
 * so a suggestion lives one iteration and a scenario that falls silent is never obeyed on a
 * stale word.
 */
public final class ReadRobotCommands extends Rule {

    /** Per slot: the iteration of the suggestion last seen there (-1: none yet). */
    private long[] seenIteration = new long[0];
    /** Per slot: the robot time at which the decision first saw that suggestion, simulated ms. */
    private long[] seenAtMs = new long[0];

    private transient long[] timeoutsMs = new long[0];
    private transient boolean anyTimeout;
    private transient long nowMs;
    private transient Suggestion winner;

    @Override
    public String scenario() {
        return DecisionMakingScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        List<StrategyTable.Entry> strategy = ctx.service(StrategyTable.class).read();
        PriorityArray priorities = ctx.memory().priorityArray();
        if (timeoutsMs.length != priorities.size()) {
            timeoutsMs = new long[priorities.size()];
        }
        Arrays.fill(timeoutsMs, 0);
        anyTimeout = false;
        for (StrategyTable.Entry e : strategy) {
            if (e.slot() >= 0 && e.slot() < priorities.size()) {
                priorities.set(e.slot(), e.priority());
                timeoutsMs[e.slot()] = e.timeoutMs();
                anyTimeout |= e.timeoutMs() > 0;
            }
        }
    }

    /** The clock is read only when a slot has a time-out: the default costs no extra query. */
    @Override
    protected void acquireConditionData(RuleContext ctx) {
        CommandArray commands = ctx.memory().commandArray();
        if (seenIteration.length != commands.size()) {
            seenIteration = new long[commands.size()];
            seenAtMs = new long[commands.size()];
            Arrays.fill(seenIteration, -1);
        }
        if (!anyTimeout) {
            return;
        }
        nowMs = ctx.service(SensorReadings.class).robotClockMs();
        for (int slot = 0; slot < commands.size(); slot++) {
            Suggestion s = commands.get(slot);
            if (s != null && s.iteration() != seenIteration[slot]) {
                seenIteration[slot] = s.iteration();
                seenAtMs[slot] = nowMs;
            }
        }
    }

    /** Condition: always; it finds the winner (or STOP). */
    @Override
    protected boolean conditions(RuleContext ctx) {
        CommandArray commands = ctx.memory().commandArray();
        winner = null;
        for (int slot : ctx.memory().priorityArray().slotsByPriority()) {
            Suggestion s = commands.get(slot);
            if (s != null && live(slot, s)) {
                winner = s;
                break;
            }
        }
        if (winner == null) {
            winner = new Suggestion(org.proactiverobotics.engine.motion.Steering.STOP, DecisionMakingScenario.NAME, ctx.iteration());
        }
        return true;
    }

    /** Expired suggestions go before anyone sees them; one-iteration ones go after the decision. */
    @Override
    protected void actions(RuleContext ctx) {
        CommandArray commands = ctx.memory().commandArray();
        for (int slot = 0; slot < commands.size(); slot++) {
            Suggestion s = commands.get(slot);
            if (s != null && !live(slot, s)) {
                commands.clear(slot);
            }
        }
        ctx.findService(DecisionObserver.class).ifPresent(o -> o.decided(ctx.iteration(), commands, winner));
        ctx.memory().values().put(SharedMemory.LAST_DECISION, winner.scenario() + " " + winner.command());
        for (int slot = 0; slot < commands.size(); slot++) {
            if (timeoutMs(slot) == 0) {
                commands.clear(slot);
            }
        }
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        if (outcome.conditionsHeld() && winner != null) {
            ctx.generate(new SendRobotCommand(winner.command(), winner.scenario()));
        }
        ctx.generate(this);
    }

    /** Time-out 0: whatever is there was entered since the last decision, which cleared the slot. */
    private boolean live(int slot, Suggestion s) {
        long timeout = timeoutMs(slot);
        return timeout == 0 || (s.iteration() == seenIteration[slot] && nowMs - seenAtMs[slot] <= timeout);
    }

    private long timeoutMs(int slot) {
        return slot < timeoutsMs.length ? timeoutsMs[slot] : 0;
    }
}
