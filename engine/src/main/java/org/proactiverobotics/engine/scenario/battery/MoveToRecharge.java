package org.proactiverobotics.engine.scenario.battery;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Drives to the recharge station, asks for RECHARGE there until the battery is back at the
 * battery_recharged level, then generates a new BatteryMonitor (which keeps what was learnt).
 * Steers like MoveToCheckpoint, as in the paper.
 */
public final class MoveToRecharge extends Rule {

    /** Charges only well inside the station, so the simulator agrees the robot is there. */
    static final double AT_STATION_FRACTION = 0.6;
    /** Close enough to the target level, percent. */
    static final double FULL_TOLERANCE_PCT = 0.5;

    private double xM;
    private double yM;
    private double radiusM;
    private DrainEstimate drain;

    private transient GpsFix position;
    private transient Heading heading;
    private transient BatteryState battery;
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
        done = battery.levelPct() >= targetPct - FULL_TOLERANCE_PCT;
        return !done;
    }

    @Override
    protected void actions(RuleContext ctx) {
        String command;
        if (position.distanceTo(xM, yM) < radiusM * AT_STATION_FRACTION) {
            command = Steering.RECHARGE;
        } else {
            DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
            command = Steering.goTo(position.xM(), position.yM(), heading.yawRad(), xM, yM, profile);
        }
        ctx.suggest(command);
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(done ? new BatteryMonitor(drain) : this);
    }
}
