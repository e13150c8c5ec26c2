package com.example.traffic;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * In a world shared with other robots, something ahead that draws nearer faster than this robot
 * drives toward it is another robot coming: veer right for {@link #VEER_MS} ms. Two robots that
 * both keep right pass each other, with nothing to agree on. A lone robot (no {@link SharedWorld}
 * service) never veers.
 */
public final class PassOnTheRight extends Rule {

    /** Something nearer than this ahead (±25°, from the rim) is watched, metres. */
    static final double WATCH_M = 0.8;
    /** Readings are compared this far apart, simulated ms. */
    static final long COMPARE_MS = 200;
    /** Drawing nearer by more than this beyond the robot's own travel is something coming, metres. */
    static final double COMING_M = 0.04;
    /** How long a veer lasts, simulated ms. */
    static final long VEER_MS = 1_000;

    // Saved with the engine state: the reading compared against, and the veer under way.
    private long thenMs = -1;
    private double thenAheadM;
    private double thenX;
    private double thenY;
    private long veerUntilMs = -1;

    private transient DistanceScan scan;
    private transient PoseEstimate pose;

    @Override
    public String scenario() {
        return KeepRightScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        scan = ctx.service(SensorReadings.class).newestScan().orElse(null);
    }

    /** Guard: other robots share the world, and a scan is there. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return ctx.findService(SharedWorld.class).isPresent() && scan != null;
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        pose = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
    }

    /** Condition: a veer under way, or something coming head-on (the reading of {@link #COMPARE_MS} ago is renewed). */
    @Override
    protected boolean conditions(RuleContext ctx) {
        if (pose == null || !pose.knowsHeading()) {
            return false;
        }
        double aheadM = scan.min(Math.toRadians(-25), Math.toRadians(25));
        long now = pose.simTimeMs();
        if (thenMs >= 0 && now - thenMs >= COMPARE_MS) {
            double ownM = (pose.xM() - thenX) * Math.cos(pose.yawRad()) + (pose.yM() - thenY) * Math.sin(pose.yawRad());
            if (aheadM < WATCH_M && thenAheadM - aheadM - ownM > COMING_M) {
                veerUntilMs = now + VEER_MS;
            }
        }
        if (thenMs < 0 || now - thenMs >= COMPARE_MS) {
            thenMs = now;
            thenAheadM = aheadM;
            thenX = pose.xM();
            thenY = pose.yM();
        }
        return now < veerUntilMs;
    }

    /** Half speed, turning right at 1 rad/s. */
    @Override
    protected void actions(RuleContext ctx) {
        DriveProfile profile = ctx.service(DriveProfile.class);
        ctx.suggest(Steering.drive(0.5 * profile.maxSpeedMps(), -1.0, profile));
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }
}
