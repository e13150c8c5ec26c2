package org.proactiverobotics.sim2d;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * A parsed and validated world file (docs/world-file.md), with every default applied.
 * <p>
 * Units are those of the file: metres, seconds, degrees, percent. Obtain one from {@link WorldFiles};
 * the canonical constructors do not validate (tests and benchmarks build worlds directly).
 *
 * @param name              the world's name (letters, digits, {@code -}, {@code _})
 * @param timeStepMs        the fixed simulation step in milliseconds (1–1000)
 * @param maxSimTimeS       the mission's time limit in simulated seconds
 * @param seed              the seed of every random draw (sensor noise)
 * @param arena             the arena: a circle centred on (0, 0) or a rectangle
 * @param robot             the robot's start pose and properties
 * @param obstacles         the static obstacles, possibly none
 * @param checkpoints       the checkpoints, visited in this order (at least one)
 * @param checkpointRadiusM how close, in metres, the robot's centre must come to a checkpoint
 * @param rechargeStation   the recharge station
 * @param battery           the battery's parameters
 * @param robots            every robot of the world with its own mission, in the file's order (at least one; the
 *                          first is {@code robot} with {@code checkpoints}); a one-robot file has one, id
 *                          {@value #SINGLE_ROBOT_ID}
 * @param rechargeStations  every recharge station (at least one; the first is {@code rechargeStation})
 */
public record WorldSpec(
        String name,
        int timeStepMs,
        double maxSimTimeS,
        long seed,
        Arena arena,
        Robot robot,
        List<Obstacle> obstacles,
        List<Checkpoint> checkpoints,
        double checkpointRadiusM,
        RechargeStation rechargeStation,
        Battery battery,
        List<RobotEntry> robots,
        List<RechargeStation> rechargeStations) {

    /** Default {@code timeStepMs}. */
    public static final int DEFAULT_TIME_STEP_MS = 32;
    /** Default {@code maxSimTimeS}. */
    public static final double DEFAULT_MAX_SIM_TIME_S = 600.0;
    /** Default {@code seed}. */
    public static final long DEFAULT_SEED = 0L;
    /** Default {@code checkpointRadiusM}. */
    public static final double DEFAULT_CHECKPOINT_RADIUS_M = 0.25;
    /** The id of the robot of a one-robot world file. */
    public static final int SINGLE_ROBOT_ID = 1;

    /** Copies the lists so that a spec cannot change after construction. */
    public WorldSpec {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(arena, "arena");
        Objects.requireNonNull(robot, "robot");
        obstacles = List.copyOf(obstacles);
        checkpoints = List.copyOf(checkpoints);
        Objects.requireNonNull(rechargeStation, "rechargeStation");
        Objects.requireNonNull(battery, "battery");
        robots = robots == null || robots.isEmpty()
                ? List.of(new RobotEntry(SINGLE_ROBOT_ID, robot, checkpoints)) : List.copyOf(robots);
        rechargeStations = rechargeStations == null || rechargeStations.isEmpty()
                ? List.of(rechargeStation) : List.copyOf(rechargeStations);
        if (!robots.get(0).robot().equals(robot) || !robots.get(0).checkpoints().equals(checkpoints)) {
            throw new IllegalArgumentException("robot and checkpoints must be the first of robots");
        }
        if (!rechargeStations.get(0).equals(rechargeStation)) {
            throw new IllegalArgumentException("rechargeStation must be the first of rechargeStations");
        }
    }

    /** A one-robot world (robot id {@value #SINGLE_ROBOT_ID}, one recharge station), as every world was before fleets. */
    public WorldSpec(String name, int timeStepMs, double maxSimTimeS, long seed, Arena arena, Robot robot,
                     List<Obstacle> obstacles, List<Checkpoint> checkpoints, double checkpointRadiusM,
                     RechargeStation rechargeStation, Battery battery) {
        this(name, timeStepMs, maxSimTimeS, seed, arena, robot, obstacles, checkpoints, checkpointRadiusM,
                rechargeStation, battery, null, null);
    }

    /**
     * A world with several robots, each with its own mission, sharing the arena, obstacles and stations.
     *
     * @param robots   at least one, ids positive and distinct (not checked here: {@link WorldFiles} validates)
     * @param stations at least one
     * @return the world; {@code robot()} and {@code checkpoints()} are the first robot's
     */
    public static WorldSpec fleet(String name, int timeStepMs, double maxSimTimeS, long seed, Arena arena,
                                  List<RobotEntry> robots, List<Obstacle> obstacles, double checkpointRadiusM,
                                  List<RechargeStation> stations, Battery battery) {
        RobotEntry first = robots.get(0);
        return new WorldSpec(name, timeStepMs, maxSimTimeS, seed, arena, first.robot(), obstacles,
                first.checkpoints(), checkpointRadiusM, stations.get(0), battery, robots, stations);
    }

    /** @return whether the world has more than one robot */
    public boolean hasSeveralRobots() {
        return robots.size() > 1;
    }

    /**
     * The world as robot {@code index} alone would see its mission: its robot and checkpoints first, every
     * station, its own first: the one nearest its start (the first of those as near); the other robots
     * are left out (what a robot's own mission rows and drive profile are made from).
     *
     * @param index the robot's position in {@link #robots()} (0-based)
     * @return a one-robot view of this world
     */
    public WorldSpec forRobot(int index) {
        RobotEntry entry = robots.get(index);
        RechargeStation own = nearestStation(entry.robot());
        List<RechargeStation> ownFirst = new ArrayList<>(rechargeStations);
        ownFirst.remove(own);
        ownFirst.add(0, own);
        return new WorldSpec(name, timeStepMs, maxSimTimeS, seed, arena, entry.robot(), obstacles,
                entry.checkpoints(), checkpointRadiusM, own, battery, List.of(entry), ownFirst);
    }

    /**
     * @param r a robot
     * @return the station nearest the robot's start (the first of those as near): the one its mission charges at
     */
    public RechargeStation nearestStation(Robot r) {
        RechargeStation nearest = rechargeStations.get(0);
        for (RechargeStation st : rechargeStations) {
            if (Math.hypot(st.x() - r.x(), st.y() - r.y()) < Math.hypot(nearest.x() - r.x(), nearest.y() - r.y())) {
                nearest = st;
            }
        }
        return nearest;
    }

    /** @return the time step in seconds */
    public double timeStepS() {
        return timeStepMs / 1000.0;
    }

    /** @return a copy of this world with other obstacles (for tests and benchmarks) */
    public WorldSpec withObstacles(List<Obstacle> newObstacles) {
        return new WorldSpec(name, timeStepMs, maxSimTimeS, seed, arena, robot, newObstacles, checkpoints,
                checkpointRadiusM, rechargeStation, battery, robots, rechargeStations);
    }

    /** @return a copy of this world with another robot (for tests and benchmarks) */
    public WorldSpec withRobot(Robot newRobot) {
        List<RobotEntry> changed = new ArrayList<>(robots);
        changed.set(0, new RobotEntry(robots.get(0).id(), newRobot, checkpoints));
        return new WorldSpec(name, timeStepMs, maxSimTimeS, seed, arena, newRobot, obstacles, checkpoints,
                checkpointRadiusM, rechargeStation, battery, changed, rechargeStations);
    }

    /** @return a copy of this world with another battery (for tests and benchmarks) */
    public WorldSpec withBattery(Battery newBattery) {
        return new WorldSpec(name, timeStepMs, maxSimTimeS, seed, arena, robot, obstacles, checkpoints,
                checkpointRadiusM, rechargeStation, newBattery, robots, rechargeStations);
    }

    /**
     * The arena, closed by a wall: a circle centred on (0, 0), or a rectangle with sides along the axes
     * (docs/world-file.md, docs/maps.md). Fields that do not apply to the shape are 0.
     *
     * @param radiusM the circle's radius to the wall's inner face, metres (0 for a rectangle)
     * @param widthM  the rectangle's extent along x between the walls' inner faces, metres (0 for a circle)
     * @param heightM the rectangle's extent along y, metres (0 for a circle)
     * @param x       the rectangle's centre x, metres (0 for a circle)
     * @param y       the rectangle's centre y, metres (0 for a circle)
     */
    public record Arena(double radiusM, double widthM, double heightM, double x, double y) {

        /** A circular arena centred on (0, 0), as every world had before rectangles. */
        public Arena(double radiusM) {
            this(radiusM, 0.0, 0.0, 0.0, 0.0);
        }

        /**
         * @param widthM  extent along x, metres
         * @param heightM extent along y, metres
         * @param x       centre x, metres
         * @param y       centre y, metres
         * @return a rectangular arena
         */
        public static Arena rectangle(double widthM, double heightM, double x, double y) {
            return new Arena(0.0, widthM, heightM, x, y);
        }

        /** @return whether this is the circle (else a rectangle) */
        public boolean isCircle() {
            return radiusM > 0.0;
        }

        /** @return the smallest x inside the arena, metres */
        public double minX() {
            return isCircle() ? -radiusM : x - widthM / 2.0;
        }

        /** @return the largest x inside the arena, metres */
        public double maxX() {
            return isCircle() ? radiusM : x + widthM / 2.0;
        }

        /** @return the smallest y inside the arena, metres */
        public double minY() {
            return isCircle() ? -radiusM : y - heightM / 2.0;
        }

        /** @return the largest y inside the arena, metres */
        public double maxY() {
            return isCircle() ? radiusM : y + heightM / 2.0;
        }

        /**
         * @return how far (px, py) is from the wall's inner face, metres: positive inside the arena, negative
         *         outside (for a rectangle, to the nearest side)
         */
        public double inside(double px, double py) {
            if (isCircle()) {
                return radiusM - Math.sqrt(px * px + py * py);
            }
            return Math.min(Math.min(px - minX(), maxX() - px), Math.min(py - minY(), maxY() - py));
        }
    }

    /**
     * The robot: a disc driven by two wheels.
     *
     * @param x            start x, metres
     * @param y            start y, metres
     * @param headingDeg   start heading, degrees (0 = +x, counter-clockwise positive)
     * @param radiusM      body radius, metres (default 0.12)
     * @param maxSpeedMps  highest wheel speed, metres per second (default 0.5)
     * @param sensorRangeM range of every distance sensor, metres (default 1.0)
     * @param sensorAnglesDeg each distance sensor's direction relative to the heading, degrees,
     *                        rightmost first (default {@link #DEFAULT_SENSOR_ANGLES_DEG})
     */
    public record Robot(double x, double y, double headingDeg, double radiusM, double maxSpeedMps, double sensorRangeM,
                        List<Double> sensorAnglesDeg) {
        /** Default {@code radiusM}. */
        public static final double DEFAULT_RADIUS_M = 0.12;
        /** Default {@code maxSpeedMps}. */
        public static final double DEFAULT_MAX_SPEED_MPS = 0.5;
        /** Default {@code sensorRangeM}. */
        public static final double DEFAULT_SENSOR_RANGE_M = 1.0;
        /**
         * Default {@code sensorAnglesDeg}: twelve rays, front-heavy, covering both sides, no more than 20°
         * apart (with eight, 45° apart at the flanks, a wall's end between them was unseen until a turning body touched it).
         */
        public static final List<Double> DEFAULT_SENSOR_ANGLES_DEG = List.of(-90.0, -70.0, -50.0, -35.0, -20.0, -8.0, 8.0, 20.0, 35.0, 50.0, 70.0, 90.0);

        /** Keeps an unmodifiable copy of the angles. */
        public Robot {
            sensorAnglesDeg = List.copyOf(sensorAnglesDeg);
        }

        /** A robot with the default distance sensors. */
        public Robot(double x, double y, double headingDeg, double radiusM, double maxSpeedMps, double sensorRangeM) {
            this(x, y, headingDeg, radiusM, maxSpeedMps, sensorRangeM, DEFAULT_SENSOR_ANGLES_DEG);
        }

        /** @return the start heading in radians */
        public double headingRad() {
            return Math.toRadians(headingDeg);
        }
    }

    /**
     * A static obstacle: a box (width × height, rotated by angleDeg about its centre) or a circle.
     * Fields that do not apply to the shape are 0.
     *
     * @param shape    {@link #BOX} or {@link #CIRCLE}
     * @param x        centre x, metres
     * @param y        centre y, metres
     * @param widthM   box extent along its own x axis, metres (0 for a circle)
     * @param heightM  box extent along its own y axis, metres (0 for a circle)
     * @param angleDeg box rotation, degrees counter-clockwise (0 for a circle)
     * @param radiusM  circle radius, metres (0 for a box)
     */
    public record Obstacle(String shape, double x, double y, double widthM, double heightM, double angleDeg,
                           double radiusM) {
        /** The {@code shape} of a box. */
        public static final String BOX = "box";
        /** The {@code shape} of a circle. */
        public static final String CIRCLE = "circle";

        /** @return a box obstacle */
        public static Obstacle box(double x, double y, double widthM, double heightM, double angleDeg) {
            return new Obstacle(BOX, x, y, widthM, heightM, angleDeg, 0.0);
        }

        /** @return a circle obstacle */
        public static Obstacle circle(double x, double y, double radiusM) {
            return new Obstacle(CIRCLE, x, y, 0.0, 0.0, 0.0, radiusM);
        }

        /** @return whether this is a box */
        public boolean isBox() {
            return BOX.equals(shape);
        }

        /** @return whether this is a circle */
        public boolean isCircle() {
            return CIRCLE.equals(shape);
        }

        /** @return the box rotation in radians */
        public double angleRad() {
            return Math.toRadians(angleDeg);
        }

        /**
         * @return the distance in metres from (px, py) to this obstacle's outline, 0 when the point is inside
         */
        public double distanceTo(double px, double py) {
            double dx = px - x;
            double dy = py - y;
            if (isCircle()) {
                return Math.max(0.0, Math.sqrt(dx * dx + dy * dy) - radiusM);
            }
            double a = angleRad();
            double cos = Math.cos(a);
            double sin = Math.sin(a);
            // The point in the box's own frame, folded into its first quadrant.
            double lx = Math.abs(dx * cos + dy * sin) - widthM / 2.0;
            double ly = Math.abs(-dx * sin + dy * cos) - heightM / 2.0;
            double ox = Math.max(lx, 0.0);
            double oy = Math.max(ly, 0.0);
            return Math.sqrt(ox * ox + oy * oy);
        }
    }

    /**
     * A checkpoint the robot must visit.
     *
     * @param x metres
     * @param y metres
     */
    public record Checkpoint(double x, double y) {
    }

    /**
     * One robot of the world and its own mission.
     *
     * @param id          the robot's id (positive; its rows' {@code robot_id})
     * @param robot       its start pose and properties
     * @param checkpoints its checkpoints, visited in this order (at least one)
     */
    public record RobotEntry(int id, Robot robot, List<Checkpoint> checkpoints) {
        /** Keeps an unmodifiable copy of the checkpoints. */
        public RobotEntry {
            Objects.requireNonNull(robot, "robot");
            checkpoints = List.copyOf(checkpoints);
        }
    }

    /**
     * The recharge station: a disc marker on the floor.
     *
     * @param x       centre x, metres
     * @param y       centre y, metres
     * @param radiusM radius, metres; the robot is at the station while its centre is within it
     */
    public record RechargeStation(double x, double y, double radiusM) {
    }

    /**
     * The battery, in percent of full charge.
     *
     * @param initial          level at start, percent (0–100; default 100)
     * @param drainPerMeter    percent lost per metre travelled (default 1.0)
     * @param rechargeTo       level charging stops at, percent (0–100; default 100)
     * @param rechargeRatePerS percent gained per second of charging (default 10)
     */
    public record Battery(double initial, double drainPerMeter, double rechargeTo, double rechargeRatePerS) {
        /** The battery used when the file has none. */
        public static final Battery DEFAULT = new Battery(100.0, 1.0, 100.0, 10.0);
    }
}
