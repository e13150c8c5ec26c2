package org.proactiverobotics.app.generate;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.SplittableRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.WorldSpec.Obstacle;
import org.proactiverobotics.sim2d.WorldValidationException;

/**
 * Draws worlds of a kind from a seed, each valid (as {@code validate} checks it) and solvable (as
 * {@link Solvability} plans it); a draw that is neither is drawn again. The same kind, seed and
 * number give the same world.
 */
public final class WorldGenerator {

    /** The kinds of world. */
    public enum Kind {
        /** Obstacles of every shape strewn between the checkpoints. */
        CLUTTERED,
        /** U-shaped cups opening towards the robot, a checkpoint behind each: local minima to get out of. */
        TRAPS,
        /**
         * Long walls across the arena, each with one gap of 1.9 to 2.9 robot diameters (0.45 to 0.7 m) at alternating ends.
         * Its time limit counts a fifth of top speed, not a third: the next checkpoint lies beyond the far end
         * from the gap, so a robot that does not know the map follows each wall the wrong way first (about
         * 3.5 times the planned path, measured, and the recharges that driving asks for).
         */
        CORRIDORS(5, 0.1),
        /** Few obstacles, far checkpoints and a battery that cannot do the tour without recharging. */
        BATTERY,
        /** A dense field of thin pillars between the start and the goal, passages down to 1.5 robot diameters. */
        PILLARS,
        /** Rooms of 2.3 to 3.5 m joined by doors of 2 to 3 robot diameters, checkpoints in other rooms. */
        ROOMS(3, 0.07),
        /** A maze of corridors 2.5 to 3.2 robot diameters wide, checkpoints in far parts of it. */
        MAZE;

        /** The tour's time limit is its planned path's time at top speed times this, plus charging and a margin. */
        private final int slowdown;
        /** The smallest robot radius its worlds are drawn for, metres (below, hardly a draw is solvable). */
        private final double minRadiusM;

        Kind() {
            this(3, MIN_RADIUS_M);
        }

        Kind(int slowdown, double minRadiusM) {
            this.slowdown = slowdown;
            this.minRadiusM = minRadiusM;
        }

        /**
         * @return the smallest robot radius this kind is drawn for, metres: for corridors and rooms the
         *         solvability check's 5 cm clearance closes passages of a few diameters of a smaller robot
         */
        public double minRadiusM() {
            return minRadiusM;
        }

        /** @return its name on the command line */
        public String label() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** @return every kind's label */
        public static List<String> labels() {
            return Arrays.stream(values()).map(Kind::label).toList();
        }
    }

    /** The smallest robot radius any kind is drawn for, metres. */
    public static final double MIN_RADIUS_M = 0.05;
    /** The largest, metres. */
    public static final double MAX_RADIUS_M = 0.3;

    /** How {@link #world} names a world: its kind's label, a dash and its number, three digits at least. */
    private static final String NAME_FORMAT = "%s-%03d";
    /** A name {@link #NAME_FORMAT} writes, read back. */
    private static final Pattern GENERATED_NAME = Pattern.compile("([a-z]+)-\\d{3,}");
    private static final double ARENA_M = 5.0;
    private static final int MAX_DRAWS = 500;
    /** The most robots a world is drawn with. */
    public static final int MAX_ROBOTS = FleetPlacement.MAX_ROBOTS;
    /** Seconds added to a fleet's time limit for each robot beyond the first: waiting for another at a door or station. */
    private static final double FLEET_WAIT_S = 30.0;

    private final Kind kind;
    private final double robotRadiusM;

    /**
     * The kind of a world this generator drew, read back from its name: {@link #world} names every
     * world {@code <kind>-<NNN>} (and {@code generate} writes it to {@code <kind>-<NNN>.json}), as
     * docs/experiments.md documents. A world file has no kind of its own, so this is the one reliable
     * source of it; any other name (a world written by hand) has none.
     *
     * @param worldName a world's name
     * @return its kind's label when the name is one of the kinds, a dash and three digits or more; else empty
     */
    public static Optional<String> kindOfName(String worldName) {
        Matcher m = GENERATED_NAME.matcher(worldName);
        return m.matches() && Kind.labels().contains(m.group(1)) ? Optional.of(m.group(1)) : Optional.empty();
    }

    /** @param kind the kind of world to draw, for the default robot (radius {@value WorldSpec.Robot#DEFAULT_RADIUS_M} m) */
    public WorldGenerator(Kind kind) {
        this(kind, WorldSpec.Robot.DEFAULT_RADIUS_M);
    }

    /**
     * @param kind         the kind of world to draw
     * @param robotRadiusM the robot's radius, metres: passages, doors and corridors scale with it
     */
    public WorldGenerator(Kind kind, double robotRadiusM) {
        this.kind = kind;
        this.robotRadiusM = robotRadiusM;
    }

    /**
     * @param seed   the sweep's seed
     * @param number the world's number, from 1
     * @return a valid, solvable world named {@code <kind>-<number>}, its noise seed drawn too
     * @throws IllegalStateException when no draw is solvable (not expected for the built-in kinds)
     */
    public WorldSpec world(long seed, int number) {
        return world(seed, number, 1);
    }

    /**
     * @param seed   the sweep's seed
     * @param number the world's number, from 1
     * @param robots how many robots, 1 to {@value #MAX_ROBOTS}: one draws the one-robot world as ever; more are
     *               placed by {@link FleetPlacement} in the same draw, each robot's mission checked solvable on
     *               its own (with the station nearest its start)
     * @return a valid, solvable world named {@code <kind>-<number>}, its noise seed drawn too
     * @throws IllegalStateException when no draw is solvable (not expected for the built-in kinds)
     */
    public WorldSpec world(long seed, int number, int robots) {
        if (robots < 1 || robots > MAX_ROBOTS) {
            throw new IllegalArgumentException("robots must be from 1 to " + MAX_ROBOTS + ": " + robots);
        }
        SplittableRandom random = new SplittableRandom(seed * 1_000_003L + number * 7_919L + kind.ordinal());
        String name = String.format(Locale.ROOT, NAME_FORMAT, kind.label(), number);
        for (int draw = 0; draw < MAX_DRAWS; draw++) {
            WorldSpec candidate = draw(name, random);
            WorldSpec valid;
            try {
                valid = WorldFiles.parse(WorldJson.of(candidate), name); // the world file's own checks
            } catch (WorldValidationException e) {
                continue;
            }
            if (robots > 1) {
                WorldSpec fleet = fleet(valid, robots, random);
                if (fleet != null) {
                    return fleet;
                }
                continue;
            }
            Solvability plan = Solvability.of(valid);
            if (!plan.solvable() || (kind == Kind.BATTERY && plan.recharges() == 0)) {
                continue;
            }
            return new WorldSpec(name, valid.timeStepMs(), timeLimitS(valid, plan), valid.seed(), valid.arena(), valid.robot(),
                    valid.obstacles(), valid.checkpoints(), valid.checkpointRadiusM(), valid.rechargeStation(), valid.battery());
        }
        throw new IllegalStateException("no solvable " + kind.label() + " world"
                + (robots > 1 ? " with " + robots + " robots" : "") + " in " + MAX_DRAWS + " draws");
    }

    /** Time for the tour at a third of top speed (a fifth for corridors), the charging, and a margin, seconds. */
    private double timeLimitS(WorldSpec mission, Solvability plan) {
        double chargeS = plan.recharges() * mission.battery().rechargeTo() / mission.battery().rechargeRatePerS();
        return Math.ceil((plan.lengthM() / (mission.robot().maxSpeedMps() / kind.slowdown) + chargeS + 60) / 10) * 10;
    }

    /**
     * @return the drawn world with N robots placed, valid and every mission solvable, its time limit the longest
     *         mission's and {@value #FLEET_WAIT_S} s for each other robot (waiting at doors and stations); null
     *         when this draw does not give one
     */
    private WorldSpec fleet(WorldSpec valid, int robots, SplittableRandom random) {
        GridPlanner planner = new GridPlanner(valid, Solvability.CLEARANCE_M);
        Solvability first = Solvability.of(valid, planner);
        if (!first.solvable() || (kind == Kind.BATTERY && first.recharges() == 0)) {
            return null;
        }
        WorldSpec placed = new FleetPlacement(valid, planner, random).place(robots);
        if (placed == null) {
            return null;
        }
        WorldSpec fleet;
        try {
            fleet = WorldFiles.parse(WorldJson.of(placed), valid.name());
        } catch (WorldValidationException e) {
            return null;
        }
        double limit = 0;
        for (int i = 0; i < robots; i++) {
            WorldSpec mission = Solvability.missionOf(fleet, i);
            Solvability plan = Solvability.of(mission, planner); // every robot has robot 1's body: one grid serves all
            if (!plan.solvable()) {
                return null;
            }
            limit = Math.max(limit, timeLimitS(mission, plan));
        }
        return WorldSpec.fleet(fleet.name(), fleet.timeStepMs(), limit + FLEET_WAIT_S * (robots - 1), fleet.seed(),
                fleet.arena(), fleet.robots(), fleet.obstacles(), fleet.checkpointRadiusM(), fleet.rechargeStations(),
                fleet.battery());
    }

    /**
     * The distance sensors of a robot of this size: the default rays for the default robot; a
     * wider one gets a scanner's fan (every 5° across ±30°, every 15° out to ±90°), since 16° between
     * the front rays leave a thin pillar straight ahead of a 0.3 m body unseen until it touches.
     *
     * @param robotRadiusM the robot's radius, metres
     * @return the sensors' angles, degrees, rightmost first
     */
    public static List<Double> sensorAnglesDeg(double robotRadiusM) {
        if (robotRadiusM <= WorldSpec.Robot.DEFAULT_RADIUS_M) {
            return WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG;
        }
        List<Double> angles = new ArrayList<>();
        for (double a = -90; a <= 90; a += a < -30 || a >= 30 ? 15 : 5) {
            angles.add(a);
        }
        return angles;
    }

    private WorldSpec draw(String name, SplittableRandom random) {
        WorldSpec.Robot robot = new WorldSpec.Robot(0.0, -4.2, 90.0, robotRadiusM,
                WorldSpec.Robot.DEFAULT_MAX_SPEED_MPS, WorldSpec.Robot.DEFAULT_SENSOR_RANGE_M, sensorAnglesDeg(robotRadiusM));
        List<Obstacle> obstacles = new ArrayList<>();
        List<WorldSpec.Checkpoint> checkpoints = new ArrayList<>();
        WorldSpec.RechargeStation station = new WorldSpec.RechargeStation(round(random.nextDouble(-3.2, -2.2)),
                round(random.nextDouble(-3.2, -2.2)), 0.35);
        WorldSpec.Battery battery = WorldSpec.Battery.DEFAULT;
        switch (kind) {
            case CLUTTERED -> clutter(random, robot, station, checkpoints, obstacles, 3 + random.nextInt(3), 10 + random.nextInt(7));
            case TRAPS -> traps(random, robot, checkpoints, obstacles);
            case CORRIDORS -> corridors(random, checkpoints, obstacles, 2 * robotRadiusM);
            case PILLARS -> pillars(random, checkpoints, obstacles, 2 * robotRadiusM);
            case ROOMS -> {
                double[] start = rooms(random, checkpoints, obstacles, 2 * robotRadiusM);
                robot = new WorldSpec.Robot(start[0], start[1], 90.0, robot.radiusM(), robot.maxSpeedMps(), robot.sensorRangeM(),
                        robot.sensorAnglesDeg());
                station = new WorldSpec.RechargeStation(start[2], start[3], 0.35);
            }
            case MAZE -> {
                double[] start = maze(random, checkpoints, obstacles, 2 * robotRadiusM);
                robot = new WorldSpec.Robot(start[0], start[1], 90.0, robot.radiusM(), robot.maxSpeedMps(), robot.sensorRangeM(),
                        robot.sensorAnglesDeg());
                station = new WorldSpec.RechargeStation(start[2], start[3], 0.35);
            }
            case BATTERY -> {
                clutter(random, robot, station, checkpoints, obstacles, 3 + random.nextInt(3), 3 + random.nextInt(5));
                battery = new WorldSpec.Battery(round(random.nextDouble(25, 45)), round(random.nextDouble(1.5, 3.0)), 100.0,
                        10.0);
            }
        }
        return new WorldSpec(name, WorldSpec.DEFAULT_TIME_STEP_MS, WorldSpec.DEFAULT_MAX_SIM_TIME_S, random.nextLong(1, 1_000_000),
                new WorldSpec.Arena(ARENA_M), robot, obstacles, checkpoints, WorldSpec.DEFAULT_CHECKPOINT_RADIUS_M, station,
                battery);
    }

    /** Checkpoints far apart, then obstacles with gaps of at least 0.65 m, 0.9 m off every point of interest. */
    private static void clutter(SplittableRandom random, WorldSpec.Robot robot, WorldSpec.RechargeStation station,
                                List<WorldSpec.Checkpoint> checkpoints, List<Obstacle> obstacles, int nCheckpoints,
                                int nObstacles) {
        List<double[]> keepClear = new ArrayList<>(List.of(new double[] {robot.x(), robot.y()},
                new double[] {station.x(), station.y()}));
        for (int attempt = 0; attempt < 1000 && checkpoints.size() < nCheckpoints; attempt++) {
            double x = random.nextDouble(-3.6, 3.6);
            double y = random.nextDouble(-3.6, 3.6);
            if (Math.hypot(x, y) < 3.8 && keepClear.stream().allMatch(p -> Math.hypot(p[0] - x, p[1] - y) > 1.6)) {
                keepClear.add(new double[] {x, y});
                checkpoints.add(new WorldSpec.Checkpoint(round(x), round(y)));
            }
        }
        List<double[]> placed = new ArrayList<>();
        for (int attempt = 0; attempt < 3000 && placed.size() < nObstacles; attempt++) {
            double x = random.nextDouble(-4.2, 4.2);
            double y = random.nextDouble(-4.2, 4.2);
            double r = random.nextDouble(0.15, 0.55);
            boolean fits = Math.hypot(x, y) + r < ARENA_M - 0.7
                    && keepClear.stream().allMatch(p -> Math.hypot(p[0] - x, p[1] - y) > r + 0.9)
                    && placed.stream().allMatch(o -> Math.hypot(o[0] - x, o[1] - y) > r + o[2] + 0.65);
            if (!fits) {
                continue;
            }
            placed.add(new double[] {x, y, r});
            obstacles.add(random.nextBoolean() ? Obstacle.circle(round(x), round(y), round(r * 0.95))
                    : Obstacle.box(round(x), round(y), round(r * 1.4), round(r * 1.0), 15.0 * random.nextInt(12)));
        }
    }

    /** One to three cups, each opening towards the point the robot comes from, a checkpoint behind it. */
    private static void traps(SplittableRandom random, WorldSpec.Robot robot, List<WorldSpec.Checkpoint> checkpoints,
                              List<Obstacle> obstacles) {
        int n = 1 + random.nextInt(3);
        double px = robot.x();
        double py = robot.y();
        for (int k = 0; k < n; k++) {
            double cx = round(random.nextDouble(-3.2, 3.2));
            double cy = round(random.nextDouble(-3.2, 3.2));
            double ux = cx - px;
            double uy = cy - py;
            double len = Math.hypot(ux, uy);
            if (len < 2.8) {
                continue;
            }
            ux /= len;
            uy /= len;
            double nx = -uy;
            double ny = ux;
            double half = random.nextDouble(0.6, 0.9); // half the cup's width
            double depth = random.nextDouble(0.7, 1.1);
            double bx = cx - 0.9 * ux; // the back wall, 0.9 m before the checkpoint
            double by = cy - 0.9 * uy;
            double angle = Math.toDegrees(Math.atan2(uy, ux));
            obstacles.add(Obstacle.box(round(bx), round(by), 0.15, round(2 * half + 0.15), round(angle)));
            for (int side = -1; side <= 1; side += 2) {
                double sx = bx - depth / 2 * ux + side * half * nx;
                double sy = by - depth / 2 * uy + side * half * ny;
                obstacles.add(Obstacle.box(round(sx), round(sy), round(depth), 0.15, round(angle)));
            }
            checkpoints.add(new WorldSpec.Checkpoint(cx, cy));
            px = cx;
            py = cy;
        }
    }

    /** Two to four walls across the arena, gaps at alternating ends, a checkpoint at the far end of each lane. */
    private static void corridors(SplittableRandom random, List<WorldSpec.Checkpoint> checkpoints, List<Obstacle> obstacles,
                                  double diameterM) {
        int walls = 2 + random.nextInt(3);
        double bottom = -3.2;
        double top = 3.2;
        double spacing = (top - bottom) / (walls - 1);
        boolean gapRight = random.nextBoolean();
        for (int w = 0; w < walls; w++) {
            double y = round(bottom + w * spacing + random.nextDouble(-0.15, 0.15));
            double half = Math.sqrt(ARENA_M * ARENA_M - y * y); // the chord at this height
            double gap = passable(random.nextDouble(1.9, 2.9) * diameterM, diameterM);
            double from = gapRight ? -half - 0.3 : -half + gap;
            double to = gapRight ? half - gap : half + 0.3;
            obstacles.add(Obstacle.box(round((from + to) / 2), y, round(to - from), 0.2, 0.0));
            // in the lane below the wall, at the gap's end: the robot must reach it to get through
            double laneY = round(y - Math.min(0.8, spacing / 2));
            double laneHalf = Math.sqrt(ARENA_M * ARENA_M - laneY * laneY);
            double cx = gapRight ? laneHalf - gap / 2 - 0.6 : -laneHalf + gap / 2 + 0.6;
            checkpoints.add(new WorldSpec.Checkpoint(round(cx), laneY));
            gapRight = !gapRight;
        }
        double lastY = round(top + 0.8);
        checkpoints.add(new WorldSpec.Checkpoint(round(random.nextDouble(-1.5, 1.5)), Math.min(lastY, 4.0)));
    }

    /**
     * Thin pillars on a jittered grid over the middle of the arena, the gaps between rims 1.5 to 2.5
     * robot diameters, a few left out; the goal beyond the field, a second checkpoint to one side.
     */
    private static void pillars(SplittableRandom random, List<WorldSpec.Checkpoint> checkpoints, List<Obstacle> obstacles,
                                double diameterM) {
        double r = random.nextDouble(0.04, 0.08);
        double gap = random.nextDouble(1.5, 2.5) * diameterM;
        double pitch = gap + 2 * r;
        double jitter = 0.1 * gap;
        for (double y = -2.6; y <= 2.6; y += pitch) {
            double shift = random.nextBoolean() ? pitch / 2 : 0;
            for (double x = -2.6 + shift; x <= 2.6; x += pitch) {
                if (random.nextDouble() < 0.12) {
                    continue;
                }
                obstacles.add(Obstacle.circle(round(x + random.nextDouble(-jitter, jitter) / 2),
                        round(y + random.nextDouble(-jitter, jitter) / 2), round(r)));
            }
        }
        checkpoints.add(new WorldSpec.Checkpoint(round(random.nextDouble(-1.5, 1.5)), 3.7));
        if (random.nextBoolean()) {
            checkpoints.add(new WorldSpec.Checkpoint(round(random.nextBoolean() ? -3.6 : 3.6), round(random.nextDouble(-1.0, 1.0))));
        }
    }

    private static final double WALL_M = 0.1;

    /**
     * A block of 2 × 2 to 3 × 3 rooms in the arena's inscribed square, each wall between two rooms
     * with a door of 2 to 3 robot diameters (every room joined through a spanning tree, a few walls
     * with a second way through); the robot starts in one room, the checkpoints are in others.
     *
     * @return the robot's start x, y and the station's x, y
     */
    private static double[] rooms(SplittableRandom random, List<WorldSpec.Checkpoint> checkpoints, List<Obstacle> obstacles,
                                  double diameterM) {
        int nx = 2 + random.nextInt(2);
        int ny = 2 + random.nextInt(2);
        double side = 6.6;
        double rw = side / nx;
        double rh = side / ny;
        double x0 = -side / 2;
        double y0 = -side / 2;
        boolean[][] doorsV = new boolean[nx - 1][ny]; // wall between room (i, j) and (i + 1, j)
        boolean[][] doorsH = new boolean[nx][ny - 1]; // wall between room (i, j) and (i, j + 1)
        spanningTree(random, nx, ny, doorsV, doorsH, 0.2);
        // the outer walls
        obstacles.add(Obstacle.box(0, round(y0 - WALL_M / 2), round(side + 2 * WALL_M), WALL_M, 0));
        obstacles.add(Obstacle.box(0, round(y0 + side + WALL_M / 2), round(side + 2 * WALL_M), WALL_M, 0));
        obstacles.add(Obstacle.box(round(x0 - WALL_M / 2), 0, WALL_M, round(side + 2 * WALL_M), 0));
        obstacles.add(Obstacle.box(round(x0 + side + WALL_M / 2), 0, WALL_M, round(side + 2 * WALL_M), 0));
        for (int i = 0; i < nx - 1; i++) {
            for (int j = 0; j < ny; j++) {
                double x = x0 + (i + 1) * rw;
                wallWithDoor(random, obstacles, true, x, y0 + j * rh, y0 + (j + 1) * rh, doorsV[i][j], diameterM);
            }
        }
        for (int i = 0; i < nx; i++) {
            for (int j = 0; j < ny - 1; j++) {
                double y = y0 + (j + 1) * rh;
                wallWithDoor(random, obstacles, false, y, x0 + i * rw, x0 + (i + 1) * rw, doorsH[i][j], diameterM);
            }
        }
        int si = random.nextInt(nx);
        int sj = random.nextInt(ny);
        List<int[]> others = new ArrayList<>();
        for (int i = 0; i < nx; i++) {
            for (int j = 0; j < ny; j++) {
                if (i != si || j != sj) {
                    others.add(new int[] {i, j});
                }
            }
        }
        int n = Math.min(others.size(), 2 + random.nextInt(2));
        for (int k = 0; k < n; k++) {
            int[] room = others.remove(random.nextInt(others.size()));
            checkpoints.add(new WorldSpec.Checkpoint(round(x0 + (room[0] + 0.5) * rw + random.nextDouble(-0.3, 0.3) * rw),
                    round(y0 + (room[1] + 0.5) * rh + random.nextDouble(-0.3, 0.3) * rh)));
        }
        double sx = x0 + (si + 0.5) * rw;
        double sy = y0 + (sj + 0.5) * rh;
        return new double[] {round(sx), round(sy - 0.25 * rh), round(sx + 0.25 * rw), round(sy + 0.2 * rh)};
    }

    /**
     * A gap or door of the width drawn, but never narrower than the solvability check's planner can
     * pass (the body, its {@link Solvability#CLEARANCE_M} each side and two of its cells): for a small
     * robot the 5 cm clearance, not the diameter, decides (radius 0.05 m: no rooms or corridors
     * world was solvable in 500 draws). The default robot and larger ones draw as before.
     */
    static double passable(double widthM, double diameterM) {
        return Math.max(widthM, diameterM + 2 * Solvability.CLEARANCE_M + 2 * GridPlanner.CELL_M);
    }

    /** A wall along x = at (vertical) or y = at, from a to b, with a door of 2 to 3 diameters when asked. */
    private static void wallWithDoor(SplittableRandom random, List<Obstacle> obstacles, boolean vertical, double at,
                                     double a, double b, boolean door, double diameterM) {
        List<double[]> pieces = new ArrayList<>();
        if (door) {
            double width = Math.min(passable(random.nextDouble(2.0, 3.0) * diameterM, diameterM), b - a - 0.7);
            double from = random.nextDouble(a + 0.3, b - 0.3 - width);
            pieces.add(new double[] {a, from});
            pieces.add(new double[] {from + width, b});
        } else {
            pieces.add(new double[] {a, b});
        }
        for (double[] p : pieces) {
            double len = p[1] - p[0];
            double mid = (p[0] + p[1]) / 2;
            obstacles.add(vertical ? Obstacle.box(round(at), round(mid), WALL_M, round(len + WALL_M), 0)
                    : Obstacle.box(round(mid), round(at), round(len + WALL_M), WALL_M, 0));
        }
    }

    /** Opens walls of a grid of cells along a random spanning tree (depth first), and a few more at random. */
    private static void spanningTree(SplittableRandom random, int nx, int ny, boolean[][] openV, boolean[][] openH,
                                     double extra) {
        boolean[][] seen = new boolean[nx][ny];
        ArrayDeque<int[]> stack = new ArrayDeque<>();
        stack.push(new int[] {0, 0});
        seen[0][0] = true;
        int[][] steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        while (!stack.isEmpty()) {
            int[] c = stack.peek();
            List<int[]> next = new ArrayList<>();
            for (int[] d : steps) {
                int i = c[0] + d[0];
                int j = c[1] + d[1];
                if (i >= 0 && j >= 0 && i < nx && j < ny && !seen[i][j]) {
                    next.add(new int[] {i, j});
                }
            }
            if (next.isEmpty()) {
                stack.pop();
                continue;
            }
            int[] n = next.get(random.nextInt(next.size()));
            if (n[0] != c[0]) {
                openV[Math.min(n[0], c[0])][c[1]] = true;
            } else {
                openH[c[0]][Math.min(n[1], c[1])] = true;
            }
            seen[n[0]][n[1]] = true;
            stack.push(n);
        }
        for (boolean[] col : openV) {
            for (int j = 0; j < col.length; j++) {
                col[j] |= random.nextDouble() < extra;
            }
        }
        for (boolean[] col : openH) {
            for (int j = 0; j < col.length; j++) {
                col[j] |= random.nextDouble() < extra;
            }
        }
    }

    /**
     * A perfect maze (depth-first) of square cells 2.5 to 3.2 robot diameters wide, 5 to 7 cells a
     * side, walls merged along each row and column; the robot starts in a corner cell, the
     * checkpoints are in two far cells.
     *
     * @return the robot's start x, y and the station's x, y
     */
    private static double[] maze(SplittableRandom random, List<WorldSpec.Checkpoint> checkpoints, List<Obstacle> obstacles,
                                 double diameterM) {
        double cell = round(random.nextDouble(2.5, 3.2) * diameterM + WALL_M);
        int n = Math.min(5 + random.nextInt(3), (int) Math.floor(6.6 / cell));
        boolean[][] openV = new boolean[n - 1][n];
        boolean[][] openH = new boolean[n][n - 1];
        spanningTree(random, n, n, openV, openH, 0.0);
        double side = n * cell;
        double x0 = -side / 2;
        double y0 = -side / 2;
        // horizontal walls: the outer two, and between rows j and j + 1, merged where consecutive
        for (int j = 0; j <= n; j++) {
            double y = y0 + j * cell;
            int i = 0;
            while (i < n) {
                if (j > 0 && j < n && openH[i][j - 1]) {
                    i++;
                    continue;
                }
                int start = i;
                while (i < n && (j == 0 || j == n || !openH[i][j - 1])) {
                    i++;
                }
                double a = x0 + start * cell;
                double b = x0 + i * cell;
                obstacles.add(Obstacle.box(round((a + b) / 2), round(y), round(b - a + WALL_M), WALL_M, 0));
            }
        }
        for (int i = 0; i <= n; i++) {
            double x = x0 + i * cell;
            int j = 0;
            while (j < n) {
                if (i > 0 && i < n && openV[i - 1][j]) {
                    j++;
                    continue;
                }
                int start = j;
                while (j < n && (i == 0 || i == n || !openV[i - 1][j])) {
                    j++;
                }
                double a = y0 + start * cell;
                double b = y0 + j * cell;
                obstacles.add(Obstacle.box(round(x), round((a + b) / 2), WALL_M, round(b - a + WALL_M), 0));
            }
        }
        checkpoints.add(new WorldSpec.Checkpoint(round(x0 + (n - 0.5) * cell), round(y0 + (n - 0.5) * cell)));
        int ci = random.nextInt(n);
        checkpoints.add(new WorldSpec.Checkpoint(round(x0 + (ci + 0.5) * cell), round(y0 + (n / 2 + 0.5) * cell)));
        double sx = x0 + 0.5 * cell;
        double sy = y0 + 0.5 * cell;
        return new double[] {round(sx), round(sy), round(sx), round(sy)};
    }

    private static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }
}
