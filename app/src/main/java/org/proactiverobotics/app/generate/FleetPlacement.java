package org.proactiverobotics.app.generate;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Turns a drawn one-robot world into one with N robots whose missions cross: robot 1 keeps its start and
 * checkpoints; robot k (k ≥ 2) starts near one of robot 1's checkpoints and has its checkpoints near the
 * starts of the robots after it (robot 1's among them), so that every robot drives into the regions the
 * others leave from, towards them. Starts are a body's width and a margin apart, off every checkpoint and
 * station; every point is reachable from robot 1's start on the planner's inflated footprint. Stations:
 * one per two robots, at most {@value #MAX_STATIONS}, the extra ones near the starts of robots 3 and 5.
 * Draws only from the random it is given, so the same draw gives the same fleet.
 */
final class FleetPlacement {

    /** The most stations a generated fleet gets: some are shared, as a fleet's stations are. */
    static final int MAX_STATIONS = 3;
    /** The most robots {@code generate --robots} places. */
    static final int MAX_ROBOTS = 8;
    /** Room kept between things placed (rims, circles), metres. */
    private static final double MARGIN_M = 0.2;
    private static final int ATTEMPTS = 400;

    private final WorldSpec base;
    private final GridPlanner planner;
    private final boolean[] reachable;
    private final SplittableRandom random;
    private final double radiusM;
    private final double checkpointRadiusM;
    private final double stationRadiusM;
    private final List<WorldSpec.Robot> starts = new ArrayList<>();
    private final List<List<WorldSpec.Checkpoint>> missions = new ArrayList<>();
    private final List<WorldSpec.RechargeStation> stations = new ArrayList<>();

    /**
     * @param base    a valid one-robot world (robot 1 and the first station)
     * @param planner its planner (with {@link Solvability#CLEARANCE_M})
     * @param random  where the draws come from
     */
    FleetPlacement(WorldSpec base, GridPlanner planner, SplittableRandom random) {
        this.base = base;
        this.planner = planner;
        this.random = random;
        this.reachable = planner.reachableFrom(base.robot().x(), base.robot().y());
        this.radiusM = base.robot().radiusM();
        this.checkpointRadiusM = base.checkpointRadiusM();
        this.stationRadiusM = base.rechargeStation().radiusM();
        starts.add(base.robot());
        missions.add(base.checkpoints());
        stations.add(base.rechargeStation());
    }

    /**
     * @param robots how many robots, 2 to {@value #MAX_ROBOTS}
     * @return the world with that many robots (ids 1 to N), or null when a point could not be placed (draw again)
     */
    WorldSpec place(int robots) {
        List<WorldSpec.Checkpoint> first = base.checkpoints();
        for (int k = 1; k < robots; k++) {
            WorldSpec.Checkpoint anchor = first.get((k - 1) % first.size());
            double[] p = near(anchor.x(), anchor.y(), 0.5, this::startFits);
            if (p == null) {
                return null;
            }
            starts.add(new WorldSpec.Robot(p[0], p[1], 0.0, radiusM, base.robot().maxSpeedMps(), base.robot().sensorRangeM(),
                    base.robot().sensorAnglesDeg()));
        }
        int nStations = Math.min(MAX_STATIONS, (robots + 1) / 2);
        for (int s = 1; s < nStations; s++) {
            WorldSpec.Robot anchor = starts.get(2 * s);
            double[] p = near(anchor.x(), anchor.y(), stationRadiusM + radiusM + MARGIN_M, this::stationFits);
            if (p == null) {
                return null;
            }
            stations.add(new WorldSpec.RechargeStation(p[0], p[1], stationRadiusM));
        }
        int perRobot = Math.max(1, Math.min(3, first.size()));
        for (int k = 1; k < robots; k++) {
            List<WorldSpec.Checkpoint> mission = new ArrayList<>();
            missions.add(mission);
            for (int c = 0; c < perRobot; c++) {
                WorldSpec.Robot anchor = starts.get((k + 1 + c) % robots == k ? (k + 2 + c) % robots : (k + 1 + c) % robots);
                WorldSpec.Robot own = starts.get(k);
                // nearer the other's start than its own: the robot drives over to where the other comes from
                double[] p = near(anchor.x(), anchor.y(), checkpointRadiusM + radiusM + MARGIN_M, (x, y) -> checkpointFits(x, y)
                        && Math.hypot(anchor.x() - x, anchor.y() - y) < Math.hypot(own.x() - x, own.y() - y));
                if (p == null) {
                    return null;
                }
                mission.add(new WorldSpec.Checkpoint(p[0], p[1]));
            }
        }
        List<WorldSpec.RobotEntry> entries = new ArrayList<>();
        for (int k = 0; k < robots; k++) {
            WorldSpec.Robot r = starts.get(k);
            double heading = r.headingDeg();
            if (k > 0) { // facing its first checkpoint
                WorldSpec.Checkpoint to = missions.get(k).get(0);
                heading = Math.rint(Math.toDegrees(Math.atan2(to.y() - r.y(), to.x() - r.x())));
            }
            r = new WorldSpec.Robot(r.x(), r.y(), heading, r.radiusM(), r.maxSpeedMps(), r.sensorRangeM(),
                    withRearRays(r.sensorAnglesDeg()));
            entries.add(new WorldSpec.RobotEntry(k + 1, r, missions.get(k)));
        }
        return WorldSpec.fleet(base.name(), base.timeStepMs(), base.maxSimTimeS(), base.seed(), base.arena(), entries,
                base.obstacles(), checkpointRadiusM, stations, base.battery());
    }

    /**
     * A robot that gives way backs out over where it came from, where another robot may have come since: the rays a
     * fleet robot is drawn with look behind too (at 150°, 180° and -150°), so that the collision monitor sees what
     * it backs toward. Angles already beyond ±90° are kept as they are.
     */
    static List<Double> withRearRays(List<Double> anglesDeg) {
        if (anglesDeg.stream().anyMatch(a -> Math.abs(a) > 90.0)) {
            return anglesDeg;
        }
        List<Double> all = new ArrayList<>();
        all.add(-150.0);
        all.addAll(anglesDeg);
        all.add(150.0);
        all.add(180.0);
        return all;
    }

    /** What a point must satisfy to be placed. */
    private interface Fit {
        boolean test(double x, double y);
    }

    /**
     * @param minM the least distance from the anchor, metres; the most grows with the attempts
     * @return a reachable point near (ax, ay), rounded to centimetres, that fits; null after {@value #ATTEMPTS} attempts
     */
    private double[] near(double ax, double ay, double minM, Fit fit) {
        for (int attempt = 0; attempt < ATTEMPTS; attempt++) {
            double angle = random.nextDouble(0, 2 * Math.PI);
            double d = minM + random.nextDouble() * (1.0 + attempt * 0.01);
            double x = round(ax + d * Math.cos(angle));
            double y = round(ay + d * Math.sin(angle));
            if (planner.within(reachable, x, y) && fit.test(x, y)) {
                return new double[] {x, y};
            }
        }
        return null;
    }

    /** A start: a body's width and a margin between rims, off every checkpoint and station. */
    private boolean startFits(double x, double y) {
        for (WorldSpec.Robot r : starts) {
            if (Math.hypot(r.x() - x, r.y() - y) < 4 * radiusM + MARGIN_M) {
                return false;
            }
        }
        return clearOfCheckpoints(x, y, checkpointRadiusM + radiusM + MARGIN_M)
                && clearOfStations(x, y, stationRadiusM + radiusM + MARGIN_M);
    }

    /** A station: no robot starts on it, off every checkpoint, apart from the others. */
    private boolean stationFits(double x, double y) {
        for (WorldSpec.Robot r : starts) {
            if (Math.hypot(r.x() - x, r.y() - y) < stationRadiusM + radiusM + MARGIN_M) {
                return false;
            }
        }
        return clearOfCheckpoints(x, y, stationRadiusM + checkpointRadiusM + MARGIN_M)
                && clearOfStations(x, y, 2 * stationRadiusM + 2 * radiusM + MARGIN_M);
    }

    /** A checkpoint: off every start and station; apart from the others by two bodies, so two robots can be on theirs. */
    private boolean checkpointFits(double x, double y) {
        for (WorldSpec.Robot r : starts) {
            if (Math.hypot(r.x() - x, r.y() - y) < checkpointRadiusM + radiusM + MARGIN_M) {
                return false;
            }
        }
        return clearOfCheckpoints(x, y, 2 * checkpointRadiusM + 2 * radiusM)
                && clearOfStations(x, y, stationRadiusM + checkpointRadiusM + MARGIN_M);
    }

    private boolean clearOfCheckpoints(double x, double y, double apartM) {
        for (List<WorldSpec.Checkpoint> mission : missions) {
            for (WorldSpec.Checkpoint c : mission) {
                if (Math.hypot(c.x() - x, c.y() - y) < apartM) {
                    return false;
                }
            }
        }
        return true;
    }

    private boolean clearOfStations(double x, double y, double apartM) {
        for (WorldSpec.RechargeStation s : stations) {
            if (Math.hypot(s.x() - x, s.y() - y) < apartM) {
                return false;
            }
        }
        return true;
    }

    private static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }
}
