package org.proactiverobotics.engine.scenario.battery;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.navigation.Route;
import org.proactiverobotics.engine.navigation.RoutePlanner;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.Station;

/**
 * Keeps the battery promise: the robot gets to the recharge station before the battery is flat,
 * whatever else happens. Two checks, every iteration; while both pass it clones itself, when one
 * fails it generates MoveToRecharge.
 * <ul>
 * <li><b>Point of no return</b>, always, whether or not the robot makes progress (lost, circling,
 * stuck on a wall): is there enough left to drive back to the station? The way back is the route
 * planned over the cells the rays have seen ({@link RoutePlanner#planOverSeen}, the way
 * MoveToRecharge drives; with unknown cells free only when the seen cells hold none; between
 * plans, the last plan plus what has been driven since, which the robot could drive back),
 * stretched by the detour factor (1.25 until a trip to the station has measured a longer one, see
 * {@link DrainEstimate#detour()}), plus a reserve. On the last leg the robot goes on past it when
 * the route planned to the last checkpoint is shorter than the way back and within reach (in a
 * shared world only until what that was to cost is spent, and while what is left still covers the
 * way back at its least cost).</li>
 * <li><b>The leg</b>: can the robot reach its next checkpoint and still get to the station from
 * there (for the last checkpoint: just reach it)? Checked only when a full charge could promise
 * the leg from the station (a recharge then helps), and not on the first leg after a recharge:
 * the robot then sets out with all a charge can give and turns back only at the point of no
 * return, so it never oscillates between the station and a leg that asks for more than a full
 * charge.</li>
 * </ul>
 * Once every checkpoint is reached a lone robot's mission is over; in a world shared with other robots
 * ({@link SharedWorld}) it drives on, out of the others' way, and the point of no return still holds.
 * The cost of travel is learnt from GPS and battery history.
 */
public final class BatteryMonitor extends Rule {

    /** Battery always kept back, percent. */
    static final double RESERVE_PCT = 5.0;
    /** Plan the way back again after driving this far, metres. */
    static final double REPLAN_AFTER_M = 0.5;
    /** ... and at least this often, iterations. */
    static final int REPLAN_EVERY = 32;
    /**
     * A way back longer than this is planned again proportionally less often (a way of 100 m after
     * 5 m and 320 iterations), metres: the estimate meanwhile is the plan plus what was driven, an
     * upper bound while the map holds, and on a large floor the plan was most of the engine's time.
     */
    static final double LONG_WAY_M = 10.0;
    /**
     * In a world shared with other robots a way back through cells no ray has seen (the seen ones hold
     * none) is taken at least this much longer than planned: walls and other robots found on it make
     * the drive longer, and at 1.25 robots turned back with 22 to 26 % and stood short of the station,
     * the way found longer than the battery (rooms-029 robot 2, corridors-021 robot 3, corridors-025
     * robot 2 of the 120 worlds of four).
     */
    static final double SHARED_DETOUR = 1.5;

    private DrainEstimate drain = new DrainEstimate();
    /** Just handed back by a recharge: the next leg is taken whatever it asks. */
    private boolean charged;
    /** The checkpoint the robot set out for after the last recharge (-1: none). */
    private int committedSeq = -1;
    /** The way back to the station planned last, metres (-1: none yet). */
    private double wayBackM = -1;
    /** Driven since the way back was planned, metres. */
    private double drivenSincePlanM;
    /** Iterations since the way back was planned. */
    private int sincePlan;
    /** Whether the way back planned last runs through cells no ray has seen (or is the straight line: no route). */
    private boolean wayBackUnseen;
    /** The route to the last checkpoint planned with the way back, metres (-1: none planned since). */
    private double finishM = -1;
    /** The last checkpoint the robot went on for past the point of no return (-1: none). */
    private int finishSeq = -1;
    /** The battery when it went on for it, percent. */
    private double finishFromPct;
    /** What finishing was to cost then, percent. */
    private double finishCostPct;
    /** Whether what was left then covered the way back at its least cost (no detour) and the reserve. */
    private boolean finishKeepsStation;

    private transient PoseEstimate position;
    private transient BatteryState battery;
    private transient Station station;
    private transient List<Checkpoint> checkpoints;
    private transient double neededPct;

    /** A monitor that starts learning from scratch. */
    public BatteryMonitor() {
    }

    /** A monitor after a recharge, keeping what was learnt. */
    BatteryMonitor(DrainEstimate drain) {
        this.drain = drain;
        this.charged = true;
    }

    @Override
    public String scenario() {
        return BatteryMonitorScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        SensorReadings readings = ctx.service(SensorReadings.class);
        position = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
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
        drivenSincePlanM += drain.lastStepM();
        sincePlan++;
        return true;
    }

    /**
     * The way back to the station, metres: planned again every {@value #REPLAN_AFTER_M} m driven
     * and every {@value #REPLAN_EVERY} iterations (walls seen since may lengthen it; proportionally
     * less often for a way longer than {@value #LONG_WAY_M} m), else the last
     * plan plus the distance driven since; the straight line when no route is known.
     */
    private double wayBackM(RuleContext ctx) {
        double straightM = position.distanceTo(station.xM(), station.yM());
        double longer = Math.max(1.0, wayBackM / LONG_WAY_M);
        if (wayBackM < 0 || drivenSincePlanM > REPLAN_AFTER_M * longer || sincePlan >= REPLAN_EVERY * longer) {
            OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), position.simTimeMs());
            double robotRadiusM = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT).axleWidthM() / 2;
            double reachM = station.radiusM() * MoveToRecharge.AT_STATION_FRACTION * 0.9;
            // the way MoveToRecharge would drive: over seen cells where they lead there; on a floor a quicker search's
            // longer way will do when it is no longer than the way was known to be (the last plan plus what was driven since)
            double boundM = wayBackM < 0 ? straightM : wayBackM + drivenSincePlanM;
            Route route = RoutePlanner.planSeenFirstBounded(map, position.xM(), position.yM(), station.xM(), station.yM(), reachM,
                    robotRadiusM, boundM);
            wayBackM = route == null ? straightM : route.lengthM();
            wayBackUnseen = route == null || !route.overSeen();
            finishM = -1;
            drivenSincePlanM = 0;
            sincePlan = 0;
        }
        return Math.max(straightM, wayBackM + drivenSincePlanM);
    }

    /**
     * @return the route planned to a checkpoint (unknown cells free, so it grows as walls appear),
     *         at least the straight line, metres; infinite when there is none. Planned on the way
     *         back's schedule ({@link #wayBackM}), and in between that plan plus what has been driven since
     */
    private double plannedWayToM(RuleContext ctx, Checkpoint c) {
        if (finishM < 0) {
            OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), position.simTimeMs());
            double robotRadiusM = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT).axleWidthM() / 2;
            Route route = RoutePlanner.plan(map, position.xM(), position.yM(), c.xM(), c.yM(), Checkpoint.routeReachM(c.radiusM()),
                    robotRadiusM);
            finishM = route == null ? Double.POSITIVE_INFINITY : route.lengthM() - drivenSincePlanM;
        }
        return Math.max(finishM + drivenSincePlanM, position.distanceTo(c.xM(), c.yM()));
    }

    /**
     * In a shared world, whether going on for the last checkpoint past the point of no return is
     * still within what it was to cost when the robot went on for it: a route through cells the map
     * lost (walls the rays took free) can hold the robot circling before a wall while the
     * battery drains; once the cost is spent without the checkpoint reached, the station it is.
     * A robot that went on with the station still within reach (what was left covered the way back
     * at its least cost, cost per metre × the way back without detour, and the reserve) goes to the
     * station as soon as it no longer is, whatever the budget.
     */
    private boolean finishWithinBudget(RuleContext ctx, Checkpoint last, double finishPct, double perMetre, double backM) {
        if (ctx.findService(SharedWorld.class).isEmpty()) {
            return true;
        }
        double stationPct = perMetre * backM + RESERVE_PCT;
        if (finishSeq != last.seq()) {
            finishSeq = last.seq();
            finishFromPct = battery.levelPct();
            finishCostPct = finishPct - RESERVE_PCT;
            finishKeepsStation = battery.levelPct() >= stationPct;
        }
        // set out with the station still within reach, it goes back before the station is out of reach: a finish that
        // then failed left robots stopped short of the station till the time limit (corridors worlds 11 and 12)
        return battery.levelPct() >= finishFromPct - finishCostPct && (!finishKeepsStation || battery.levelPct() >= stationPct);
    }

    /**
     * Condition: a recharge is needed and would help. It would help while the battery is below the
     * level a recharge gives. It is needed past the point of no return (just enough left to reach
     * the station on the detoured way back), or, once the cost of travel has been measured and
     * except on the first leg after a recharge, when the next checkpoint and then the station
     * (for the last checkpoint: just the checkpoint) are beyond what is left.
     */
    @Override
    protected boolean conditions(RuleContext ctx) {
        Checkpoint next = checkpoints.stream().filter(c -> !c.reached()).findFirst().orElse(null);
        if (next == null) {
            // a robot that is done among others drives back to its start: its way back to the station still counts
            return ctx.findService(SharedWorld.class).isPresent() && pastNoReturn(ctx);
        }
        if (charged) {
            committedSeq = next.seq();
            charged = false;
        }
        double fullPct = ctx.service(MissionTables.class).rechargeLevelPct().orElse(100.0);
        if (battery.levelPct() >= fullPct - MoveToRecharge.FULL_TOLERANCE_PCT) {
            return false;
        }
        double perMetre = drain.pctPerMetre();
        double detour = drain.detour();
        double backM = wayBackM(ctx);
        double backPct = perMetre * wayBackDetour(ctx) * backM + RESERVE_PCT;
        boolean last = next.seq() == checkpoints.get(checkpoints.size() - 1).seq();
        neededPct = backPct;
        if (battery.levelPct() < backPct) {
            if (last) {
                double finishPct = perMetre * detour * plannedWayToM(ctx, next) + RESERVE_PCT;
                if (finishPct <= backPct && battery.levelPct() >= finishPct && finishWithinBudget(ctx, next, finishPct, perMetre, backM)) {
                    neededPct = finishPct;
                    return false; // the last checkpoint is nearer than the station by route, and within reach: finishing is the safer way
                }
            }
            return true;
        }
        if (!drain.learnt() || next.seq() == committedSeq) {
            return false;
        }
        double nextToStationM = last ? 0.0 : Math.hypot(station.xM() - next.xM(), station.yM() - next.yM());
        double fromStationPct = perMetre * detour
                * (Math.hypot(station.xM() - next.xM(), station.yM() - next.yM()) + nextToStationM) + RESERVE_PCT;
        if (fromStationPct > fullPct) {
            return false; // a full charge cannot promise this leg either: go on, turn back at the point of no return
        }
        double metres = position.distanceTo(next.xM(), next.yM()) + nextToStationM;
        neededPct = Math.max(backPct, perMetre * detour * metres + RESERVE_PCT);
        return battery.levelPct() < neededPct;
    }

    /** Whether the battery is below what driving back to the station needs, once every checkpoint is reached. */
    private boolean pastNoReturn(RuleContext ctx) {
        double fullPct = ctx.service(MissionTables.class).rechargeLevelPct().orElse(100.0);
        if (battery.levelPct() >= fullPct - MoveToRecharge.FULL_TOLERANCE_PCT) {
            return false;
        }
        double backM = wayBackM(ctx);
        neededPct = drain.pctPerMetre() * wayBackDetour(ctx) * backM + RESERVE_PCT;
        return battery.levelPct() < neededPct;
    }

    /**
     * @return the detour the way back is taken with: the learnt one, at least {@value #SHARED_DETOUR} in a
     *         shared world for a way through cells no ray has seen (call after {@link #wayBackM})
     */
    private double wayBackDetour(RuleContext ctx) {
        return wayBackUnseen && ctx.findService(SharedWorld.class).isPresent() ? Math.max(SHARED_DETOUR, drain.detour()) : drain.detour();
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
