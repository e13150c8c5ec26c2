package com.example.park;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.Station;

/**
 * Guard: every checkpoint is reached. Then it suggests heading for the recharge station, and
 * STOP once the robot is within half the station's radius: the robot parks where it can charge.
 */
public final class Park extends Rule {

    private transient boolean allReached;
    private transient Station station;
    private transient PoseEstimate pose;

    @Override
    public String scenario() {
        return ReturnToStationScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        List<Checkpoint> checkpoints = ctx.service(MissionTables.class).checkpoints();
        allReached = !checkpoints.isEmpty() && checkpoints.stream().allMatch(Checkpoint::reached);
    }

    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return allReached;
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        station = ctx.service(MissionTables.class).rechargeStation().orElse(null);
        pose = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return station != null && pose != null && pose.knowsHeading();
    }

    @Override
    protected void actions(RuleContext ctx) {
        if (pose.distanceTo(station.xM(), station.yM()) <= station.radiusM() / 2) {
            ctx.suggest(Steering.STOP);
        } else {
            ctx.suggest(Steering.goTo(pose.xM(), pose.yM(), pose.yawRad(), station.xM(), station.yM(),
                    ctx.service(DriveProfile.class)));
        }
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }
}
