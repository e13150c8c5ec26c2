package com.example.park;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.Station;

/**
 * Guard: every checkpoint is reached. Then it suggests heading for the recharge station, and
 * STOP once the robot is within half the station's radius: the robot parks where it can charge.
 */
public final class Park extends Rule {

    private transient boolean allReached;
    private transient Station station;
    private transient GpsFix gps;
    private transient Heading heading;

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
        SensorReadings readings = ctx.service(SensorReadings.class);
        station = ctx.service(MissionTables.class).rechargeStation().orElse(null);
        gps = readings.newestGps().orElse(null);
        heading = readings.newestHeading().orElse(null);
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return station != null && gps != null && heading != null;
    }

    @Override
    protected void actions(RuleContext ctx) {
        if (gps.distanceTo(station.xM(), station.yM()) <= station.radiusM() / 2) {
            ctx.suggest(Steering.STOP);
        } else {
            ctx.suggest(Steering.goTo(gps.xM(), gps.yM(), heading.yawRad(), station.xM(), station.yM(),
                    ctx.service(DriveProfile.class)));
        }
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }
}
