package org.proactiverobotics.engine.scenario.decision;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.RuleFailure;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Writes one decided command to engine_comments, once; it is not regenerated. It runs in the
 * iteration after the decision, after the other scenarios: when the scenario whose suggestion
 * won has failed since (in this iteration), the command is withdrawn and STOP is sent instead,
 * so that no word of a failing scenario reaches the robot.
 */
public final class SendRobotCommand extends Rule {

    private static final String STOP = org.proactiverobotics.engine.motion.Steering.STOP;

    private String command;
    private String winner;

    private SendRobotCommand() {
    }

    /**
     * @param command  the command text
     * @param winner the scenario whose suggestion it was
     */
    public SendRobotCommand(String command, String winner) {
        this.command = command;
        this.winner = winner;
    }

    /** @return the command text */
    public String command() {
        return command;
    }

    @Override
    public String scenario() {
        return DecisionMakingScenario.NAME;
    }

    @Override
    protected void actions(RuleContext ctx) {
        long simTimeMs = Math.max(0, ctx.service(SensorReadings.class).robotClockMs());
        if (failedThisIteration(ctx, winner)) {
            ctx.service(EngineComments.class).send(ctx.iteration(), simTimeMs, DecisionMakingScenario.NAME, STOP);
        } else {
            ctx.service(EngineComments.class).send(ctx.iteration(), simTimeMs, winner, command);
        }
    }

    private static boolean failedThisIteration(RuleContext ctx, String scenario) {
        List<RuleFailure> failures = ctx.failures();
        for (int i = failures.size() - 1; i >= 0 && failures.get(i).iteration() == ctx.iteration(); i--) {
            if (failures.get(i).scenario().equals(scenario)) {
                return true;
            }
        }
        return false;
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        // sent once: not regenerated
    }
}
