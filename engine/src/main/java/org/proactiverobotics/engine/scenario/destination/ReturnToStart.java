package org.proactiverobotics.engine.scenario.destination;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.navigation.ParkingPlace;
import org.proactiverobotics.engine.navigation.RouteFollower;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * In a world shared with other robots, once every checkpoint is reached: drives back to where the robot started
 * (its {@code initial_pose}), as a fleet robot returns to its parking place, so that a robot that is done does not
 * stand on the others' way or checkpoints. It parks not on the start itself but on the nearest place of its map
 * that closes no way ({@link ParkingPlace}): a start in a gap's mouth would shut the only way through. It follows a route planned on the map like {@link MoveToCheckpoint}
 * (the collision monitor and Yield still rank above it, the battery scenario still takes it to charge), then
 * suggests STOP there; pushed more than {@value #LEAVE_M} m off it (it gave way), it drives back. When no plan
 * finds a way there for {@value #NO_ROUTE_MS} ms (another robot stands on it, or it is walled in), or the drive
 * has taken longer than {@link #budgetMs} allows, it parks instead at the nearest such place to where it stands
 * (once), and failing that too gives up for good and stops where it is: no endless re-planning, no battery
 * spent going nowhere. Standing there (or given up), when its rays find something within {@value #BESIDE_M} m that
 * was not there when it stopped for {@value #STEP_ASIDE_MS} ms (another robot waiting for the way it stands in),
 * it steps aside to the parking place nearest a point {@value #STEP_ASIDE_M} m away from it, at most
 * {@value #MAX_STEPS_ASIDE} times. Clones itself to the run's end; a checkpoint not yet reached (the
 * mission got a new one) hands back to {@link GetCheckpoint}.
 */
public final class ReturnToStart extends Rule {

    /** How long no plan may find a way to the start before the robot stops where it is, simulated ms. */
    static final long NO_ROUTE_MS = 10_000;
    /** A parked robot pushed farther than this from its start drives back, metres. */
    static final double LEAVE_M = 0.3;
    /** The fixed part of the time the drive back may take, simulated ms. */
    static final long BUDGET_BASE_MS = 60_000;
    /** The drive back may take this many times the straight line at top speed, on top of the fixed part. */
    static final double BUDGET_FACTOR = 4.0;
    /** Something a ray finds this near the rim, nearer than when the robot stopped there, stands beside it, metres. */
    static final double BESIDE_M = 0.5;
    /** How long something may stand beside a robot that is done before it steps aside, simulated ms. */
    static final long STEP_ASIDE_MS = 8_000;
    /** How far away from what stands beside it a robot steps aside (then to the nearest parking place there), metres. */
    static final double STEP_ASIDE_M = 0.8;
    /** At most this many steps aside: two robots that are done do not chase each other round the floor. */
    static final int MAX_STEPS_ASIDE = 3;

    private double xM;
    private double yM;
    /** Where it parks, metres (chosen on its map at the first iteration, and again once if it cannot get there). */
    private double parkX;
    private double parkY;
    /** 0: no place chosen yet; 1: near the start; 2: near where it stood when it could not get to the first. */
    private int placeChoice;
    /** The route and its re-planning (saved with the rule). */
    private RouteFollower route = new RouteFollower();
    /** The side the robot last turned to, +1 left, -1 right, 0 none. */
    private int behindSide;
    /** The simulated time since which no plan has found a route, ms (-1: the last plan found one). */
    private long noRouteSinceMs = -1;
    /** Whether the robot stands at its start (it stops there). */
    private boolean parked;
    /** Whether it gave up: it stops where it is until the run ends. */
    private boolean gaveUp;
    /** How long it drove for this rule so far, and may, simulated ms (-1: not set out yet). */
    private long drivenMs;
    private long budgetMs = -1;
    /** The simulated time of the last iteration, ms (-1: none yet). */
    private long lastMs = -1;
    /** The scan when it stopped at its place (or gave up), metres from the rim per ray (null: not standing). */
    private double[] standScan;
    /** Since when something has stood beside it, simulated ms (-1: nothing). */
    private long besideSinceMs = -1;
    /** How many times it stepped aside. */
    private int stepsAside;

    private transient PoseEstimate position;
    private transient boolean newCheckpoint;
    /** The unit vector from what stands beside the robot toward it, as the last watch found it (null: nothing). */
    private transient double[] beside;

    private ReturnToStart() {
    }

    /**
     * @param xM the start's x, metres
     * @param yM the start's y, metres
     */
    public ReturnToStart(double xM, double yM) {
        this.xM = xM;
        this.yM = yM;
    }

    @Override
    public String scenario() {
        return ReachDestinationScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        position = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
        newCheckpoint = ctx.service(MissionTables.class).checkpoints().stream().anyMatch(c -> !c.reached());
    }

    /** Guard: the robot's pose is known, and no checkpoint waits (else GetCheckpoint takes over). */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return !newCheckpoint && position != null && position.knowsHeading();
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return true;
    }

    @Override
    protected void actions(RuleContext ctx) {
        long now = position.simTimeMs();
        boolean driving = RouteFollower.droveFor(ctx.memory().values().get(SharedMemory.LAST_DECISION), scenario());
        if (driving && lastMs >= 0) {
            drivenMs += now - lastMs;
        }
        lastMs = now;
        DriveProfile profile = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT);
        double radiusM = profile.axleWidthM() / 2;
        if (gaveUp) {
            if (!besideTooLong(ctx, now) || !stepAside(ctx, now, radiusM)) {
                ctx.suggest(Steering.STOP);
                return;
            }
            gaveUp = false;
        }
        OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), now);
        if (placeChoice == 0) {
            double[] place = ParkingPlace.near(map, xM, yM, radiusM);
            parkX = place[0];
            parkY = place[1];
            placeChoice = 1;
        }
        double awayM = position.distanceTo(parkX, parkY);
        if (awayM < radiusM / 2 || parked && awayM < LEAVE_M) {
            if (!parked) {
                parked = true;
                route = new RouteFollower();
                noRouteSinceMs = -1;
                standScan = null;
            }
            if (!besideTooLong(ctx, now) || !stepAside(ctx, now, radiusM)) {
                ctx.suggest(Steering.STOP);
                return;
            }
            awayM = position.distanceTo(parkX, parkY);
        }
        if (parked || budgetMs < 0) { // setting out, first or again
            parked = false;
            budgetMs = drivenMs + BUDGET_BASE_MS + (long) (BUDGET_FACTOR * 1000 * awayM / profile.maxSpeedMps());
        }
        BeliefObserver belief = ctx.findService(BeliefObserver.class).orElse(null);
        RouteFollower.Status status = route.step(map, position.xM(), position.yM(), position.yawRad(), parkX, parkY,
                radiusM / 2 * 0.9, radiusM, now, driving);
        if (belief != null && route.planned()) {
            belief.route(ctx.iteration(), scenario(), route.waypointsX(), route.waypointsY());
        }
        if (status == RouteFollower.Status.NO_ROUTE) {
            if (noRouteSinceMs < 0) {
                noRouteSinceMs = now;
            }
            if (now - noRouteSinceMs >= NO_ROUTE_MS) {
                giveUp(map, radiusM);
            }
            ctx.suggest(Steering.STOP);
            return;
        }
        noRouteSinceMs = -1;
        if (drivenMs > budgetMs) {
            giveUp(map, radiusM); // a start it cannot get to: it stays near where it is rather than roam
            ctx.suggest(Steering.STOP);
            return;
        }
        if (status == RouteFollower.Status.BACK_OFF) {
            ctx.suggest(RouteFollower.backOffCommand(profile));
            return;
        }
        behindSide = Steering.turnSide(position.xM(), position.yM(), position.yawRad(), route.targetX(), route.targetY(), behindSide);
        ctx.suggest(Steering.goTo(position.xM(), position.yM(), position.yawRad(), route.targetX(), route.targetY(), profile, behindSide));
    }

    /**
     * Watches, while the robot stands, for something beside it that was not there when it stopped: another robot
     * waiting for the way it stands in (it knows the others only by its rays).
     *
     * @return whether something has stood beside it for {@value #STEP_ASIDE_MS} ms
     */
    private boolean besideTooLong(RuleContext ctx, long now) {
        DistanceScan scan = ctx.service(SensorReadings.class).newestScan().orElse(null);
        if (scan == null || stepsAside >= MAX_STEPS_ASIDE) {
            return false;
        }
        if (standScan == null || standScan.length != scan.distancesM().length) {
            standScan = scan.distancesM().clone();
            besideSinceMs = -1;
            return false;
        }
        beside = besideDirection(scan);
        if (beside == null) {
            besideSinceMs = -1;
            return false;
        }
        if (besideSinceMs < 0) {
            besideSinceMs = now;
        }
        return now - besideSinceMs >= STEP_ASIDE_MS;
    }

    /** @return the unit vector, world frame, from what stands beside the robot toward the robot, or null if nothing does */
    private double[] besideDirection(DistanceScan scan) {
        double sx = 0;
        double sy = 0;
        int rays = 0;
        for (int k = 0; k < scan.distancesM().length; k++) {
            double d = scan.distancesM()[k];
            if (d < BESIDE_M && d < standScan[k] - 0.1) { // nearer than what stood there: it came
                double a = position.yawRad() + scan.anglesRad()[k];
                sx -= Math.cos(a);
                sy -= Math.sin(a);
                rays++;
            }
        }
        double len = Math.hypot(sx, sy);
        return rays == 0 || len < 1e-9 ? null : new double[] {sx / len, sy / len};
    }

    /**
     * Steps aside: parks at the place nearest to a point {@value #STEP_ASIDE_M} m away from what stands beside it.
     *
     * @return whether it found such a place away from where it stands (then it drives there)
     */
    private boolean stepAside(RuleContext ctx, long now, double radiusM) {
        double[] away = beside; // what besideTooLong just found, from the same scan
        besideSinceMs = -1;
        standScan = null;
        if (away == null) {
            return false;
        }
        stepsAside++;
        OccupancyMap map = ctx.service(KnownMap.class).current(ctx.iteration(), now);
        double[] place = ParkingPlace.near(map, position.xM() + STEP_ASIDE_M * away[0],
                position.yM() + STEP_ASIDE_M * away[1], radiusM);
        if (position.distanceTo(place[0], place[1]) < LEAVE_M) {
            return false;
        }
        setOutFor(place);
        return true;
    }

    /** Drives for a new parking place: a new route, watch and budget. */
    private void setOutFor(double[] place) {
        parkX = place[0];
        parkY = place[1];
        route = new RouteFollower();
        noRouteSinceMs = -1;
        budgetMs = -1;
    }

    /**
     * The place it drove for cannot be got to: the first time, it parks at the place nearest to where it stands
     * that closes no way (it may stand in a doorway); the second, it stops for good.
     */
    private void giveUp(OccupancyMap map, double radiusM) {
        if (placeChoice == 1) {
            double[] place = ParkingPlace.near(map, position.xM(), position.yM(), radiusM);
            placeChoice = 2;
            if (position.distanceTo(place[0], place[1]) >= radiusM / 2) {
                setOutFor(place);
                return;
            }
        }
        gaveUp = true;
        standScan = null; // what stands beside it is judged from here
    }

    /** @return where it parks (or drives to park): {x, y}, metres */
    public double[] place() {
        return new double[] {parkX, parkY};
    }

    /** @return whether the robot stands at its parking place */
    public boolean parked() {
        return parked;
    }

    /** @return whether it gave up getting there and stays where it is */
    public boolean gaveUp() {
        return gaveUp;
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(newCheckpoint ? new GetCheckpoint() : this);
    }
}
