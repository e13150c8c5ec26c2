package org.proactiverobotics.engine.scenario.destination;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.InitialPose;
import org.proactiverobotics.engine.tables.MissionTables;

/**
 * Finds the first checkpoint not yet reached and generates MoveToCheckpoint for it. When every
 * checkpoint is reached the destination is reached: it suggests STOP and keeps looking, in
 * case the mission gets new checkpoints; in a world shared with other robots ({@link SharedWorld}) whose
 * mission says where the robot started, it generates {@link ReturnToStart} instead, which drives the robot out
 * of the others' way. When that checkpoint is marked unreachable the mission is over: it suggests STOP too.
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
            return;
        }
        InitialPose start = outcome.guardsHeld() && next == null && ctx.findService(SharedWorld.class).isPresent()
                ? ctx.service(MissionTables.class).initialPose().orElse(null) : null;
        if (start != null) { // done among other robots: it leaves the way, back to where it started
            ctx.generate(new ReturnToStart(start.xM(), start.yM()));
        } else {
            ctx.generate(this);
        }
    }
}
