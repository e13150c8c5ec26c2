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
 * Gives way to something that came at the robot head-on. Between two walls (a corridor, a door)
 * it backs off for at least
 * {@value #BACK_MS} ms and on while both sides are narrow (a corridor: the rays at
 * {@value #SIDE_DEG}° and beyond read less than {@value #WIDE_M} m on the left and on the right),
 * at most {@value #BACK_MAX_MS} ms, so that it leaves a corridor for a wider place the other can
 * pass it in (it stops backing when its map shows something behind); in the open it does not back
 * off (that costs battery, and the other's route goes round a robot that stands still). Then it waits, stopped, for a time its own robot id sets ({@link #waitMs}), and
 * hands back to {@link WatchTraffic}. Two robots that meet both give way, and the one with the
 * shorter wait goes first; the other, still waiting, sees it come and backs off again, until it
 * is out of the way. Something that comes again while the robot waits starts the backing again.
 * Symmetry is broken with what each robot knows of itself: its id and its clock. While the battery
 * scenario calls the robot to its station ({@link BatteryCall}) it does not back off, or stops
 * backing: the battery drains per metre driven, so a wait stopped costs nothing and a back-off
 * spends what the way to the station needs.
 */
public final class GiveWay extends Rule {

    /** How long the robot backs off each time something comes, simulated ms. */
    static final long BACK_MS = 1_500;
    /** Backing on in a narrow place stops after this long all told, simulated ms. */
    static final long BACK_MAX_MS = 12_000;
    /** Backing speed, as a share of the top speed (the rays look ahead: it backs over the way it came). */
    static final double BACK_SPEED = 0.6;
    /** Rays this far or farther from the heading look sideways, degrees. */
    static final double SIDE_DEG = 60;
    /** A side is narrow when a sideways ray reads less than this from the rim, metres (0.18 m in a 0.6 m corridor). */
    static final double WIDE_M = 0.4;
    /** The shortest wait after backing off, simulated ms. */
    static final long WAIT_BASE_MS = 800;
    /** Each robot id waits this much longer than the one before, simulated ms (ids 1..{@value #WAIT_IDS} wait apart). */
    static final long WAIT_STEP_MS = 1_200;
    /** Waits repeat every this many ids. */
    static final int WAIT_IDS = 6;
    /** Turn rate per metre of difference between the two sides while backing between walls, rad/s per metre. */
    static final double CENTRING_GAIN = 2.0;
    /** The fastest centring turn, rad/s. */
    static final double MAX_CENTRING_RAD_S = 0.8;
    /** The robot does not back into a cell its map has occupied within its radius plus this, metres. */
    static final double BEHIND_MARGIN_M = 0.01;
    /** The map is looked at this far behind the robot, metres. */
    static final double BEHIND_LOOK_M = 0.1;

    private Oncoming oncoming;
    /** Until when the robot backs off, simulated ms (-1: set at the first run). */
    private long backUntilMs = -1;
    /** Until when it waits, simulated ms. */
    private long waitUntilMs;
    /** Since when it backs off this time, simulated ms. */
    private long backFromMs;
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
        // the battery calls the robot to its station: backing off would spend what the way there needs; it only stops
        boolean called = BatteryCall.callsNow(ctx);
        boolean coming = scan != null && Math.abs(scan.simTimeMs() - now) <= WatchTraffic.SAME_MOMENT_MS && oncoming.observe(pose, scan, WatchTraffic.radiusM(ctx));
        if (backUntilMs < 0 || (coming && now >= backUntilMs)) {
            // (again: it came on while the robot waited) between two walls it backs out; in the open it
            // only stops, which costs no battery, and the other's route goes round it
            backFromMs = now;
            backUntilMs = narrow() && !called ? now + BACK_MS : now;
            waitUntilMs = now + waitMs(ctx.robotId());
        }
        if (called && now < backUntilMs) {
            backUntilMs = now; // called while backing: it stops where it is and waits
            waitUntilMs = now + waitMs(ctx.robotId());
        }
        if (!called && now >= backUntilMs && now - backFromMs < BACK_MAX_MS && backUntilMs > backFromMs && narrow()) {
            backUntilMs = now + 1; // still between two walls: on out of the corridor
        }
        if (now < backUntilMs) {
            waitUntilMs = backUntilMs + waitMs(ctx.robotId());
            DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
            if (blockedBehind(ctx, profile)) {
                backUntilMs = now; // nowhere to back to: wait where it is
                backFromMs = now;
                waitUntilMs = now + waitMs(ctx.robotId());
                ctx.suggest(Steering.STOP);
            } else {
                ctx.suggest(Steering.drive(-BACK_SPEED * profile.maxSpeedMps(), centring(), profile));
            }
            return;
        }
        done = now >= waitUntilMs;
        if (!done) {
            ctx.suggest(Steering.STOP);
        }
    }

    /**
     * @return the turn rate that keeps the robot backing in the middle between two walls (rad/s, counter-clockwise
     *         positive: backing, a turn to the right moves it left), 0 where a side is open
     */
    private double centring() {
        double[] sides = sides();
        if (!(sides[0] < WIDE_M && sides[1] < WIDE_M)) {
            return 0.0;
        }
        return Math.max(-MAX_CENTRING_RAD_S, Math.min(MAX_CENTRING_RAD_S, CENTRING_GAIN * (sides[1] - sides[0])));
    }

    /** Whether both sides are narrow, as the sideways rays read them now. */
    private boolean narrow() {
        double[] sides = sides();
        return sides[0] < WIDE_M && sides[1] < WIDE_M;
    }

    /** @return the nearest reading of the sideways rays on the left and on the right, metres (+∞ with no scan) */
    private double[] sides() {
        if (scan == null) {
            return new double[] {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        }
        double left = Double.POSITIVE_INFINITY;
        double right = Double.POSITIVE_INFINITY;
        double side = Math.toRadians(SIDE_DEG);
        for (int k = 0; k < scan.anglesRad().length; k++) {
            double a = scan.anglesRad()[k];
            double d = scan.distancesM()[k];
            if (a >= side) {
                left = Math.min(left, d);
            } else if (a <= -side) {
                right = Math.min(right, d);
            }
        }
        return new double[] {left, right};
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
