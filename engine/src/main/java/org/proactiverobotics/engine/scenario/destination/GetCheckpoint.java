package org.proactiverobotics.engine.scenario.destination;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.MissionTables;

/**
 * Finds the first checkpoint not yet reached and generates MoveToCheckpoint for it. When every
 * checkpoint is reached the destination is reached: it suggests STOP and keeps looking, in
 * case the mission gets new checkpoints. When that checkpoint is marked unreachable the mission
 * is over: it suggests STOP too.
 */
public final class GetCheckpoint extends Rule {

    private transient List<Checkpoint> all;
    private transient Checkpoint next;

    @Override
    public String scenario() {
        return ReachDestinationScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        all = ctx.service(MissionTables.class).checkpoints();
        next = all.stream().filter(c -> !c.reached()).findFirst().orElse(null);
    }

    /** Guard: the mission has checkpoints at all (they are seeded by the robot side). */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return !all.isEmpty();
    }

    /** Condition: every checkpoint is reached, or the next one cannot be. */
    @Override
    protected boolean conditions(RuleContext ctx) {
        return next == null || next.unreachable();
    }

    @Override
    protected void actions(RuleContext ctx) {
        ctx.suggest(Steering.STOP);
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        if (outcome.guardsHeld() && next != null && !next.unreachable()) {
            ctx.generate(new MoveToCheckpoint(next.seq(), next.xM(), next.yM(), next.radiusM()));
        } else {
            ctx.generate(this);
        }
    }
}
