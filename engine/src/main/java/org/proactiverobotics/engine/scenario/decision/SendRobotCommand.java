package org.proactiverobotics.engine.scenario.decision;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;

/** Writes one decided command to engine_comments, once; it is not regenerated. */
public final class SendRobotCommand extends Rule {

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
        long simTimeMs = Math.max(0, ctx.service(SensorReadings.class).newestSimTimeMs(Sensor.GPS));
        ctx.service(EngineComments.class).send(ctx.iteration(), simTimeMs, winner, command);
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        // sent once: not regenerated
    }
}
