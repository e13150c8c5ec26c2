package org.proactiverobotics.engine.scenario.battery;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.motion.Clearance;
import org.proactiverobotics.engine.motion.CollisionReflex;
import org.proactiverobotics.engine.motion.ControlPeriod;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.ClosedPlaces;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.navigation.LookAgainAsks;
import org.proactiverobotics.engine.navigation.RouteFollower;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Drives to the recharge station, asks for RECHARGE there until the battery is back at the
 * battery_recharged level, then generates a new BatteryMonitor (which keeps what was learnt).
 * Steers like MoveToCheckpoint, as in the paper: along a route planned on the map known so far
 * ({@link RouteFollower}, re-planned as walls appear), over the cells the rays have seen where they
 * lead to the station (the way BatteryMonitor counted), with the shared collision reflex
 * ({@link CollisionReflex}, its distances derived from the robot's speed and body) beneath, so that
 * a recharge is safe under any strategy, even one that ranks it above obstacle avoidance. The route
 * follower watches the progress as MoveToCheckpoint's does: a gap the planner lets the body through
 * and the reflex does not (no progress for {@value RouteFollower#STALL_MS} ms) is closed on the map,
 * the robot backs off and plans round it; when only such closed places lead to the station it
 * stops rather than turn on the spot. It measures how much
 * longer than the planned way the way driven to the station was ({@link DrainEstimate#trip}).
 */
public final class MoveToRecharge extends Rule {

    /** Charges only well inside the station, so the simulator agrees the robot is there. */
    static final double AT_STATION_FRACTION = 0.6;
    /**
     * Once arrived, it keeps charging while the battery says it charges, or for
     * {@value #CHARGE_START_MS} ms (a charging robot does not move: a fix that strays is noise), or
     * while the GPS puts it this deep in the station: a noisy fix
     * near the arrival edge would otherwise alternate RECHARGE and a drive, each a new charging
     * session (realistic noise, 5 cm: 10 to 14 sessions for one recharge).
     */
    static final double STAY_FRACTION = 0.85;
    /** After arriving it stays this long whatever the GPS says, ms: the battery's readings lag the RECHARGE command. */
    static final long CHARGE_START_MS = 500;
    /** Close enough to the target level, percent. */
    static final double FULL_TOLERANCE_PCT = 0.5;
    /** A scan this far behind the heading is stale: driving blind, milliseconds. */
    static final long STALE_SCAN_MS = 500;

    private double xM;
    private double yM;
    private double radiusM;
    private DrainEstimate drain;
    private CollisionReflex reflex = new CollisionReflex();
    private ControlPeriod period = new ControlPeriod();
    /** The route to the station and its re-planning. */
    private RouteFollower route = RouteFollower.overSeenCells();
    /** The side the robot last turned to, +1 left, -1 right, 0 none: kept for a target straight behind. */
    private int behindSide;
    /** The planned way to the station when the trip began, metres (-1: not yet known). */
    private double tripPlannedM = -1;
    /** Distance driven on the trip so far, metres. */
    private double tripDrivenM;
    private boolean arrived;
    /** Whether the last command was this rule's own STOP for a way longer than the battery: time so spent is no stall. */
    private boolean heldForBattery;
    /** Since when it has been held so, simulated ms (-1: not held). */
    private long heldSinceMs = -1;
    /** Its asks to look again while held, this trip (saved with the rule). */
    private LookAgainAsks lookAgainAsks = new LookAgainAsks();
    /** When it arrived, simulated ms: it stays {@value #CHARGE_START_MS} ms, until the battery can say whether it charges. */
    private long arrivedMs;

    private transient PoseEstimate position;
    private transient BatteryState battery;
    private transient DistanceScan scan;
    private transient double targetPct;
    private transient boolean done;
    private transient double aimX;
    private transient double aimY;

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
        position = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
        battery = readings.newestBattery().orElse(null);
        scan = readings.newestScan().orElse(null);
        targetPct = ctx.service(MissionTables.class).rechargeLevelPct().orElse(100.0);
    }

    /** Guard: the pose (heading included) and the battery are known. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return position != null && position.knowsHeading() && battery != null;
    }

    /** Condition: the recharge is not finished yet. */
    @Override
    protected boolean conditions(RuleContext ctx) {
        drain.position(position.xM(), position.yM());
        drain.battery(battery.simTimeMs(), battery.levelPct(), battery.charging());
        if (tripPlannedM >= 0 && !arrived) {
            tripDrivenM += drain.lastStepM();
        }
        done = battery.levelPct() >= targetPct - FULL_TOLERANCE_PCT;
        return !done;
    }

    @Override
    protected void actions(RuleContext ctx) {
        double fromStationM = position.distanceTo(xM, yM);
        boolean staying = arrived && (battery.charging() || battery.simTimeMs() <= arrivedMs + CHARGE_START_MS
                || fromStationM < radiusM * STAY_FRACTION);
        if (fromStationM < radiusM * AT_STATION_FRACTION || staying) {
            if (!arrived) {
                arrived = true;
                arrivedMs = position.simTimeMs();
                drain.trip(tripDrivenM, tripPlannedM);
            }
            ctx.suggest(Steering.RECHARGE);
            return;
        }
        DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
        OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), position.simTimeMs());
        aimX = xM;
        aimY = yM;
        RouteFollower.Status status = route.step(map, position.xM(), position.yM(), position.yawRad(), xM, yM,
                radiusM * AT_STATION_FRACTION * 0.9, profile.axleWidthM() / 2, position.simTimeMs(),
                drivingForThis(ctx) && !heldForBattery);
        if (status == RouteFollower.Status.TARGET) {
            aimX = route.targetX();
            aimY = route.targetY();
        } // no route on the map known so far: straight at the station, the reflex beneath
        BeliefObserver belief = ctx.findService(BeliefObserver.class).orElse(null);
        if (belief != null) {
            belief.pose(ctx.iteration(), position.xM(), position.yM(), position.yawRad());
            if (route.closedNow()) {
                belief.wayClosed(ctx.iteration(), scenario(), route.closed().newestReason());
            }
            if (route.planned()) {
                belief.route(ctx.iteration(), scenario(), route.waypointsX(), route.waypointsY());
            }
        }
        if (tripPlannedM < 0) {
            tripPlannedM = route.remainingM(position.xM(), position.yM(), xM, yM);
        }
        String command;
        heldForBattery = cannotMakeIt(ctx);
        lookAgainWhileHeld(ctx);
        if (heldForBattery) {
            command = Steering.STOP; // what is left would run flat on the way the map knows: keep it, stopped, till the way opens
        } else if (status == RouteFollower.Status.BACK_OFF) {
            command = RouteFollower.backOffCommand(profile); // a stall in a narrow place: back off, then plan round it
        } else if (status == RouteFollower.Status.NO_ROUTE && !route.closed().isEmpty()) {
            command = Steering.STOP; // only the narrow places it could not pass lead there: wait, never turn on the spot for ever
        } else {
            behindSide = Steering.turnSide(position.xM(), position.yM(), position.yawRad(), aimX, aimY, behindSide);
            command = Steering.goTo(position.xM(), position.yM(), position.yawRad(), aimX, aimY, profile, behindSide);
        }
        if (scan != null) {
            if (Math.abs(position.simTimeMs() - scan.simTimeMs()) > STALE_SCAN_MS) {
                command = Steering.STOP; // the distance readings lag: never drive blind
            } else {
                String veto = reflex.vet(command, scan, map, position.xM(), position.yM(), position.yawRad(), profile,
                        Clearance.of(profile, period.observe(scan.simTimeMs()), scan.rangeM()));
                command = veto == null ? command : veto;
            }
        }
        ctx.suggest(command);
    }

    /**
     * In a shared world, whether the battery left is less than the way to the station the map
     * knows now costs at the cost of travel learnt (without detour, the least it could cost): a
     * robot that drove on would run flat on the way (a way that other robots block, or a route
     * through walls the map lost, held robots circling before them till they were flat). Stopped,
     * it keeps its charge (the battery drains per metre driven) and drives on once a shorter
     * way opens. A lone robot's trip is as it always was.
     */
    private boolean cannotMakeIt(RuleContext ctx) {
        if (ctx.findService(SharedWorld.class).isEmpty()) {
            return false;
        }
        double leftM = Math.max(0.0, route.remainingM(position.xM(), position.yM(), xM, yM) - radiusM * AT_STATION_FRACTION);
        return battery.levelPct() < drain.pctPerMetre() * leftM;
    }

    /**
     * Held for the battery {@value LookAgainAsks#AFTER_MS} ms, at most {@value LookAgainAsks#LIMIT} times a trip, the
     * robot asks the mapping to let go of what moved in ({@link SharedWorld#LOOK_AGAIN}): a robot that stood in
     * the short way may have left, and stopped, this robot's rays cannot see round it. Only while a checkpoint
     * waits: a robot that is done loses nothing standing, and one that looked again drove a way that then grew
     * down to 1.2 % (corridors 15 robot 3 of the generated worlds of four robots).
     */
    private void lookAgainWhileHeld(RuleContext ctx) {
        if (!heldForBattery || ctx.service(MissionTables.class).checkpoints().stream().allMatch(c -> c.reached())) {
            heldSinceMs = -1;
            return;
        }
        if (heldSinceMs < 0) {
            heldSinceMs = position.simTimeMs();
        }
        lookAgainAsks.askWhenDue(ctx.memory().values(), heldSinceMs, position.simTimeMs());
    }

    /** @return the places the route to the station closed after stalls (do not change) */
    public ClosedPlaces closedPlaces() {
        return route.closed();
    }

    /** Whether the robot drove for this trip last iteration: its command won, or the obstacle avoidance amended it. */
    private boolean drivingForThis(RuleContext ctx) {
        return RouteFollower.droveFor(ctx.memory().values().get(SharedMemory.LAST_DECISION), scenario());
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(done ? new BatteryMonitor(drain) : this);
    }
}
