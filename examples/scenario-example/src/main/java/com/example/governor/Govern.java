package com.example.governor;

import java.util.Optional;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.navigation.RouteFollower;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * When an obstacle is within {@link #slowWithinM} ahead (±60°), suggests heading for the next
 * checkpoint at no more than {@link #slowSpeedMps}, along the route the engine's navigation
 * library plans on the map known so far (straight at the checkpoint would drive into the
 * obstacle). Lazy evaluation at work: the guard needs only the distance scan; the pose estimate,
 * checkpoints and map are read only when it holds.
 */
public final class Govern extends Rule {

    /** Saved with the engine state (non-transient): an obstacle closer than this slows the robot, metres. */
    private double slowWithinM = 0.5;
    /** The top wheel speed near obstacles, metres per second. */
    private double slowSpeedMps = 0.2;
    /** The route to the checkpoint: plain fields, saved with the rule like the two above. */
    private RouteFollower route = new RouteFollower();

    // Acquired each iteration: transient, never saved.
    private transient double nearestM;
    private transient PoseEstimate pose;
    private transient Checkpoint target;

    @Override
    public String scenario() {
        return SpeedGovernorScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        Optional<DistanceScan> scan = ctx.service(SensorReadings.class).newestScan();
        nearestM = scan.map(s -> s.min(Math.toRadians(-60), Math.toRadians(60))).orElse(Double.POSITIVE_INFINITY);
    }

    /** Guard: something is close ahead. A NaN reading counts as close (never as free space). */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return !(nearestM >= slowWithinM);
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        pose = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
        target = ctx.service(MissionTables.class).checkpoints().stream().filter(c -> !c.reached()).findFirst().orElse(null);
    }

    /** Condition: the robot knows where it is, which way it faces, and where to go. */
    @Override
    protected boolean conditions(RuleContext ctx) {
        return pose != null && pose.knowsHeading() && target != null;
    }

    @Override
    protected void actions(RuleContext ctx) {
        DriveProfile slow = new DriveProfile(slowSpeedMps, ctx.service(DriveProfile.class).axleWidthM());
        OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), pose.simTimeMs());
        double aimX = target.xM();
        double aimY = target.yM();
        if (route.step(map, pose.xM(), pose.yM(), target.xM(), target.yM(), 0.5 * target.radiusM(),
                slow.axleWidthM() / 2) == RouteFollower.Status.TARGET) {
            aimX = route.targetX();
            aimY = route.targetY();
        }
        ctx.suggest(Steering.goTo(pose.xM(), pose.yM(), pose.yawRad(), aimX, aimY, slow));
    }

    /** Always runs: the rule clones itself to watch again in the next iteration. */
    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }
}
