package org.proactiverobotics.engine.scenario.battery;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.Station;

/**
 * Can the robot reach its next checkpoint and still get to the recharge station from there (or,
 * for the last checkpoint, just reach it)? While yes it clones itself; if not it generates
 * MoveToRecharge. The cost of travel is learnt from GPS and battery history; straight-line
 * distances are stretched by a detour factor for obstacles, and a reserve is kept.
 */
public final class BatteryMonitor extends Rule {

    /** Paths are longer than straight lines around obstacles. */
    static final double DETOUR_FACTOR = 1.4;
    /** Battery always kept back, percent. */
    static final double RESERVE_PCT = 5.0;

    private DrainEstimate drain = new DrainEstimate();

    private transient GpsFix position;
    private transient BatteryState battery;
    private transient Station station;
    private transient List<Checkpoint> checkpoints;
    private transient double neededPct;

    /** A monitor that starts learning from scratch. */
    public BatteryMonitor() {
    }

    BatteryMonitor(DrainEstimate drain) {
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
        battery = readings.newestBattery().orElse(null);
        station = ctx.service(MissionTables.class).rechargeStation().orElse(null);
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        checkpoints = ctx.service(MissionTables.class).checkpoints();
    }

    /** Guard: position, battery and station are known (and the estimate learns from them). */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        if (position == null || battery == null || station == null) {
            return false;
        }
        drain.position(position.xM(), position.yM());
        drain.battery(battery.simTimeMs(), battery.levelPct(), battery.charging());
        return true;
    }

    /**
     * Condition: the battery is too low to reach the next checkpoint and then the station (for
     * the last checkpoint: to reach it), and a recharge would help (the battery is below the
     * level a recharge gives; otherwise going on is the best there is). Until the cost of travel
     * has been measured, only the point of no return counts: just enough left to reach the
     * station at the cautious prior cost.
     */
    @Override
    protected boolean conditions(RuleContext ctx) {
        Checkpoint next = checkpoints.stream().filter(c -> !c.reached()).findFirst().orElse(null);
        if (next == null) {
            return false;
        }
        double fullPct = ctx.service(MissionTables.class).rechargeLevelPct().orElse(100.0);
        if (battery.levelPct() >= fullPct - MoveToRecharge.FULL_TOLERANCE_PCT) {
            return false;
        }
        double perMetre = drain.pctPerMetre() * DETOUR_FACTOR;
        if (!drain.learnt()) {
            neededPct = perMetre * position.distanceTo(station.xM(), station.yM()) + RESERVE_PCT;
            return battery.levelPct() < neededPct;
        }
        boolean last = next.seq() == checkpoints.get(checkpoints.size() - 1).seq();
        double metres = position.distanceTo(next.xM(), next.yM())
                + (last ? 0.0 : Math.hypot(station.xM() - next.xM(), station.yM() - next.yM()));
        neededPct = perMetre * metres + RESERVE_PCT;
        return battery.levelPct() < neededPct;
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        if (outcome.conditionsHeld()) {
            ctx.generate(new MoveToRecharge(station.xM(), station.yM(), station.radiusM(), drain));
        } else {
            ctx.generate(this);
        }
    }

    /** @return the battery the robot needed at the last check, percent */
    double neededPct() {
        return neededPct;
    }
}
