package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.Station;

/**
 * Watches the way every iteration, suggesting nothing: when something comes at the robot head-on
 * ({@link Oncoming}) it hands over to {@link GiveWay}; when the robot drives to the recharge
 * station and its rays find the station taken ({@link StationView}) it hands over to
 * {@link WaitForStation}. A robot that charges never gives way (it would leave the station it
 * waited for), nor does one the battery calls to its station ({@link BatteryCall}). After a wait for
 * the station that ran out ({@link WaitForStation#WAIT_MAX_MS}) it does not wait there again for a while. Clones itself otherwise.
 */
public final class WatchTraffic extends Rule {

    /** A pose and a scan this far apart in simulated time are not one moment, ms. */
    static final long SAME_MOMENT_MS = 40;

    private Oncoming oncoming = new Oncoming();
    /** Until when a taken station does not make the robot wait, simulated ms (its wait there ran out). */
    private long noStationWaitUntilMs;

    private transient PoseEstimate pose;
    private transient DistanceScan scan;
    private transient BatteryState battery;
    private transient Station station;
    private transient boolean giveWay;

    /** Watching from the start. */
    public WatchTraffic() {
    }

    /** @param oncoming what the front rays saw lately (kept across a hand-over) */
    WatchTraffic(Oncoming oncoming) {
        this.oncoming = oncoming;
    }

    /**
     * @param oncoming             what the front rays saw lately
     * @param noStationWaitUntilMs until when a taken station does not make the robot wait, simulated ms
     */
    WatchTraffic(Oncoming oncoming, long noStationWaitUntilMs) {
        this.oncoming = oncoming;
        this.noStationWaitUntilMs = noStationWaitUntilMs;
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

    /** Guard: a pose with its heading and a scan of the same moment. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return pose != null && pose.knowsHeading() && scan != null && Math.abs(pose.simTimeMs() - scan.simTimeMs()) <= SAME_MOMENT_MS;
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        battery = ctx.service(SensorReadings.class).newestBattery().orElse(null);
        station = ctx.service(MissionTables.class).rechargeStation().orElse(null);
    }

    /**
     * Condition: not charging, and something comes head-on while the battery does not call the robot
     * to its station ({@link BatteryCall}), or the station the robot drives to is taken.
     */
    @Override
    protected boolean conditions(RuleContext ctx) {
        boolean coming = oncoming.observe(pose, scan, radiusM(ctx)); // every scan is remembered, whatever follows
        String last = ctx.memory().values().getOrDefault(SharedMemory.LAST_DECISION, "");
        if ((battery != null && battery.charging()) || last.endsWith(" RECHARGE")) {
            return false;
        }
        // the battery calls the robot to its station: it does not give way (others see it come and give way to it)
        giveWay = coming && !BatteryCall.callsNow(ctx);
        return giveWay || (StationView.headingThere(last) && pose.simTimeMs() >= noStationWaitUntilMs
                && StationView.taken(station, pose, scan, radiusM(ctx)));
    }

    /** @return the robot's radius, half its axle width, metres */
    static double radiusM(RuleContext ctx) {
        return ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT).axleWidthM() / 2;
    }

    /** Nothing to suggest: the hand-over is the action. */
    @Override
    protected void actions(RuleContext ctx) {
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        if (outcome != Outcome.ACTIONS_RUN) {
            ctx.generate(this);
        } else if (giveWay) {
            ctx.generate(new GiveWay(oncoming));
        } else {
            ctx.generate(new WaitForStation(oncoming));
        }
    }
}
