package org.proactiverobotics.engine.scenario.battery;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.BoundaryFollower;
import org.proactiverobotics.engine.motion.Clearance;
import org.proactiverobotics.engine.motion.ControlPeriod;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Drives to the recharge station, asks for RECHARGE there until the battery is back at the
 * battery_recharged level, then generates a new BatteryMonitor (which keeps what was learnt).
 * Steers like MoveToCheckpoint, as in the paper, and gets round obstacles on its own with the
 * shared boundary-following reflex ({@link BoundaryFollower}, with the clearance derived from the
 * robot's speed and body), so that a recharge never depends on another scenario letting go of a
 * wall: the strategies rank this scenario's suggestions above obstacle avoidance's. It measures
 * how much longer than the straight line the way to the station was ({@link DrainEstimate#trip}).
 */
public final class MoveToRecharge extends Rule {

    /** Charges only well inside the station, so the simulator agrees the robot is there. */
    static final double AT_STATION_FRACTION = 0.6;
    /** Close enough to the target level, percent. */
    static final double FULL_TOLERANCE_PCT = 0.5;
    /** A scan this far behind the heading is stale: driving blind, milliseconds. */
    static final long STALE_SCAN_MS = 500;
    /** Half the sector checked toward the station, radians. */
    private static final double SECTOR_RAD = Math.toRadians(25);
    /** The flanks reach this far from the heading, radians. */
    private static final double SIDE_RAD = Math.toRadians(100);
    /** Beyond this bearing the station is behind the rays, radians. */
    private static final double SEEN_BEARING_RAD = Math.toRadians(80);

    private double xM;
    private double yM;
    private double radiusM;
    private DrainEstimate drain;
    private BoundaryFollower follower = new BoundaryFollower();
    private ControlPeriod period = new ControlPeriod();
    /** Straight-line distance to the station when the trip began, metres (-1: not yet known). */
    private double tripStraightM = -1;
    /** Distance driven on the trip so far, metres. */
    private double tripDrivenM;
    private boolean arrived;

    private transient GpsFix position;
    private transient Heading heading;
    private transient BatteryState battery;
    private transient DistanceScan scan;
    private transient double targetPct;
    private transient boolean done;

    private MoveToRecharge() {
    }

    MoveToRecharge(double xM, double yM, double radiusM, DrainEstimate drain) {
        this.xM = xM;
        this.yM = yM;
        this.radiusM = radiusM;
        this.drain = drain;
    }

    @Override
    public String scenario() {
        return BatteryMonitorScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        SensorReadings readings = ctx.service(SensorReadings.class);
        position = readings.newestGps().orElse(null);
        heading = readings.newestHeading().orElse(null);
        battery = readings.newestBattery().orElse(null);
        scan = readings.newestScan().orElse(null);
        targetPct = ctx.service(MissionTables.class).rechargeLevelPct().orElse(100.0);
    }

    /** Guard: position, heading and battery are known. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return position != null && heading != null && battery != null;
    }

    /** Condition: the recharge is not finished yet. */
    @Override
    protected boolean conditions(RuleContext ctx) {
        drain.position(position.xM(), position.yM());
        drain.battery(battery.simTimeMs(), battery.levelPct(), battery.charging());
        if (tripStraightM < 0) {
            tripStraightM = position.distanceTo(xM, yM);
        } else if (!arrived) {
            tripDrivenM += drain.lastStepM();
        }
        done = battery.levelPct() >= targetPct - FULL_TOLERANCE_PCT;
        return !done;
    }

    @Override
    protected void actions(RuleContext ctx) {
        if (position.distanceTo(xM, yM) < radiusM * AT_STATION_FRACTION) {
            if (!arrived) {
                arrived = true;
                drain.trip(tripDrivenM, tripStraightM);
            }
            ctx.suggest(Steering.RECHARGE);
            return;
        }
        DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
        String command = null;
        if (scan != null) {
            if (Math.abs(heading.simTimeMs() - scan.simTimeMs()) > STALE_SCAN_MS) {
                command = Steering.STOP; // the distance readings lag: never drive blind
            } else {
                Clearance clearance = Clearance.of(profile, period.observe(scan.simTimeMs()), scan.rangeM());
                if (wayToStationClear(clearance)) {
                    follower.release(); // head for the station: no wall to follow away from it
                } else {
                    command = follower.decide(scan, heading.yawRad(), profile, clearance);
                }
            }
        }
        if (command == null) {
            command = Steering.goTo(position.xM(), position.yM(), heading.yawRad(), xM, yM, profile);
        }
        ctx.suggest(command);
    }

    /**
     * Whether the robot may head straight for the station: nothing is about to be hit ahead or
     * graze a flank, and the rays toward the station (±25°) are clear for the release distance, or (before any
     * boundary is followed) the station is behind, where turning on the spot toward it is safe.
     */
    private boolean wayToStationClear(Clearance clearance) {
        double front = scan.min(-SECTOR_RAD, SECTOR_RAD);
        if (front < clearance.engageFrontM() && follower.following()) {
            return false;
        }
        double bearing = Steering.wrap(Math.atan2(yM - position.yM(), xM - position.xM()) - heading.yawRad());
        if (Math.abs(bearing) > SEEN_BEARING_RAD) {
            return !follower.following() && front >= clearance.imminentM();
        }
        double towardStation = scan.min(bearing - SECTOR_RAD, bearing + SECTOR_RAD);
        double needed = Math.min(clearance.releaseFrontM(), Math.max(clearance.engageAheadM(), position.distanceTo(xM, yM)));
        double sides = Math.min(scan.min(-SIDE_RAD, -SECTOR_RAD), scan.min(SECTOR_RAD, SIDE_RAD));
        return towardStation > needed && front >= clearance.engageFrontM() && sides >= clearance.engageSideM();
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(done ? new BatteryMonitor(drain) : this);
    }
}
