package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Gives way to something that came at the robot head-on: backs off straight for
 * {@value #BACK_MS} ms (toward the wider place it came from; it stops backing when its map shows
 * something behind), then waits, stopped, for a time its own robot id sets ({@link #waitMs}), and
 * hands back to {@link WatchTraffic}. Two robots that meet both give way, and the one with the
 * shorter wait goes first; the other, still waiting, sees it come and backs off again, until it
 * is out of the way. Something that comes again while the robot waits starts the backing again.
 * Symmetry is broken with what each robot knows of itself: its id and its clock.
 */
public final class GiveWay extends Rule {

    /** How long the robot backs off each time something comes, simulated ms. */
    static final long BACK_MS = 1_500;
    /** Backing speed, as a share of the top speed (the rays look ahead: it backs over the way it came, slowly). */
    static final double BACK_SPEED = 0.4;
    /** The shortest wait after backing off, simulated ms. */
    static final long WAIT_BASE_MS = 800;
    /** Each robot id waits this much longer than the one before, simulated ms (ids 1..{@value #WAIT_IDS} wait apart). */
    static final long WAIT_STEP_MS = 1_200;
    /** Waits repeat every this many ids. */
    static final int WAIT_IDS = 6;
    /** The robot does not back into a cell its map has occupied within its radius plus this, metres. */
    static final double BEHIND_MARGIN_M = 0.03;
    /** The map is looked at this far behind the robot, metres. */
    static final double BEHIND_LOOK_M = 0.1;

    private Oncoming oncoming;
    /** Until when the robot backs off, simulated ms (-1: set at the first run). */
    private long backUntilMs = -1;
    /** Until when it waits, simulated ms. */
    private long waitUntilMs;
    private boolean done;

    private transient PoseEstimate pose;
    private transient DistanceScan scan;

    private GiveWay() {
    }

    /** @param oncoming what the front rays saw lately */
    GiveWay(Oncoming oncoming) {
        this.oncoming = oncoming;
    }

    /**
     * @param robotId the robot's own id
     * @return how long it waits after backing off: {@value #WAIT_BASE_MS} ms plus {@value #WAIT_STEP_MS} ms
     *         per id before it (ids {@value #WAIT_IDS} apart wait alike), simulated ms
     */
    public static long waitMs(int robotId) {
        return WAIT_BASE_MS + WAIT_STEP_MS * Math.floorMod(robotId - 1, WAIT_IDS);
    }

    @Override
    public String scenario() {
        return YieldScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        pose = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
        scan = ctx.service(SensorReadings.class).newestScan().orElse(null);
    }

    /** Guard: the pose, heading included, is known. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return pose != null && pose.knowsHeading();
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return true;
    }

    @Override
    protected void actions(RuleContext ctx) {
        long now = pose.simTimeMs();
        boolean coming = scan != null && Math.abs(scan.simTimeMs() - now) <= WatchTraffic.SAME_MOMENT_MS && oncoming.observe(pose, scan);
        if (backUntilMs < 0 || (coming && now >= backUntilMs)) {
            backUntilMs = now + BACK_MS; // (again): it came on while the robot waited
            waitUntilMs = backUntilMs + waitMs(ctx.robotId());
        }
        if (now < backUntilMs) {
            DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
            if (blockedBehind(ctx, profile)) {
                backUntilMs = now; // nowhere to back to: wait where it is
                ctx.suggest(Steering.STOP);
            } else {
                ctx.suggest(Steering.drive(-BACK_SPEED * profile.maxSpeedMps(), 0.0, profile));
            }
            return;
        }
        done = now >= waitUntilMs;
        if (!done) {
            ctx.suggest(Steering.STOP);
        }
    }

    /** Whether the map has something occupied right behind the robot, within its radius. */
    private boolean blockedBehind(RuleContext ctx, DriveProfile profile) {
        OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), pose.simTimeMs());
        double bx = pose.xM() - Math.cos(pose.yawRad()) * BEHIND_LOOK_M;
        double by = pose.yM() - Math.sin(pose.yawRad()) * BEHIND_LOOK_M;
        return map.occupiedApproached(pose.xM(), pose.yM(), bx, by, profile.axleWidthM() / 2 + BEHIND_MARGIN_M);
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(done ? new WatchTraffic(oncoming) : this);
    }
}
