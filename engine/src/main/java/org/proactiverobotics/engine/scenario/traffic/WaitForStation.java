package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.Station;

/**
 * Waits near a recharge station that something takes (a robot charging on it): stopped, where it
 * is, until its rays have seen the station free for {@value #FREE_FOR_MS} ms, then hands back to
 * {@link WatchTraffic} (and the battery scenario drives on). The battery drains per metre driven,
 * so waiting costs nothing; wandering about would. Something that comes at it head-on meanwhile
 * is given way to ({@link GiveWay}): the robot leaving the station may need the way it waits in.
 * It waits at most {@value #WAIT_MAX_MS} ms plus its id's wait ({@link GiveWay#waitMs}), then
 * drives on for {@value #GO_MS} ms without waiting: robots that wait round a free station see each
 * other's bodies within reach of its centre and take it for taken (four of six robots waited so to
 * the end, 400 s, once nothing they saw came at them); the one with the shortest wait goes first.
 */
public final class WaitForStation extends Rule {

    /** The station must look free this long before the robot drives on, simulated ms. */
    static final long FREE_FOR_MS = 500;
    /** The longest wait before the robot's id's own wait is added, simulated ms. */
    static final long WAIT_MAX_MS = 6_000;
    /** After a wait that ran out, the robot drives on this long before it waits again, simulated ms. */
    static final long GO_MS = 3_000;

    private Oncoming oncoming;
    /** Since when the station looks free, simulated ms (-1: it looks taken). */
    private long freeSinceMs = -1;
    /** Since when it waits, simulated ms (-1: set at the first run). */
    private long waitingSinceMs = -1;
    /** Whether the wait ran out. */
    private boolean waitedLongest;

    private transient PoseEstimate pose;
    private transient DistanceScan scan;
    private transient Station station;
    private transient boolean free;
    private transient boolean coming;

    private WaitForStation() {
    }

    /** @param oncoming what the front rays saw lately */
    WaitForStation(Oncoming oncoming) {
        this.oncoming = oncoming;
    }

    @Override
    public String scenario() {
        return YieldScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        pose = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
        scan = ctx.service(SensorReadings.class).newestScan().orElse(null);
        station = ctx.service(MissionTables.class).rechargeStation().orElse(null);
    }

    /** Guard: a pose with its heading and a scan of the same moment. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return pose != null && pose.knowsHeading() && scan != null
                && Math.abs(pose.simTimeMs() - scan.simTimeMs()) <= WatchTraffic.SAME_MOMENT_MS;
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return true;
    }

    @Override
    protected void actions(RuleContext ctx) {
        coming = oncoming.observe(pose, scan, WatchTraffic.radiusM(ctx));
        if (waitingSinceMs < 0) {
            waitingSinceMs = pose.simTimeMs();
        }
        waitedLongest = pose.simTimeMs() - waitingSinceMs >= WAIT_MAX_MS + GiveWay.waitMs(ctx.robotId());
        if (StationView.taken(station, pose, scan, WatchTraffic.radiusM(ctx))) {
            freeSinceMs = -1;
        } else if (freeSinceMs < 0) {
            freeSinceMs = pose.simTimeMs();
        }
        free = freeSinceMs >= 0 && pose.simTimeMs() - freeSinceMs >= FREE_FOR_MS;
        if (!free && !coming && !waitedLongest) {
            ctx.suggest(Steering.STOP);
        }
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        if (coming) {
            ctx.generate(new GiveWay(oncoming));
        } else if (waitedLongest && !free) {
            ctx.generate(new WatchTraffic(oncoming, pose.simTimeMs() + GO_MS)); // it goes; the others see it come
        } else {
            ctx.generate(free ? new WatchTraffic(oncoming) : this);
        }
    }
}
