package org.proactiverobotics.engine.scenario.decision;

import java.util.List;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.PriorityArray;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * Each iteration: loads the strategy into the PriorityArray, takes the highest priority, reads
 * the CommandArray at that index, and if it holds a command generates SendRobotCommand for it;
 * if empty, tries the next highest. With every slot empty the robot is told to stop. The
 * CommandArray is then cleared: a suggestion lives one iteration, so a scenario that falls
 * silent is never obeyed on a stale word. Runs last, so it sees every suggestion of the
 * iteration.
 */
public final class ReadRobotCommands extends Rule {

    private transient Suggestion winner;

    @Override
    public String scenario() {
        return DecisionMakingScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        List<StrategyTable.Entry> strategy = ctx.service(StrategyTable.class).read();
        PriorityArray priorities = ctx.memory().priorityArray();
        for (StrategyTable.Entry e : strategy) {
            if (e.slot() >= 0 && e.slot() < priorities.size()) {
                priorities.set(e.slot(), e.priority());
            }
        }
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        CommandArray commands = ctx.memory().commandArray();
        winner = null;
        for (int slot : ctx.memory().priorityArray().slotsByPriority()) {
            Suggestion s = commands.get(slot);
            if (s != null) {
                winner = s;
                break;
            }
        }
        if (winner == null) {
            winner = new Suggestion("STOP", DecisionMakingScenario.NAME, ctx.iteration());
        }
        return true;
    }

    @Override
    protected void actions(RuleContext ctx) {
        CommandArray commands = ctx.memory().commandArray();
        ctx.findService(DecisionObserver.class).ifPresent(o -> o.decided(ctx.iteration(), commands, winner));
        commands.clear();
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        if (outcome.conditionsHeld() && winner != null) {
            ctx.generate(new SendRobotCommand(winner.command(), winner.scenario()));
        }
        ctx.generate(this);
    }
}
