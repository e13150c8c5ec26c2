package org.proactiverobotics.app.generate;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
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
        /** Long walls across the arena with a gap at alternating ends: a serpentine to follow. */
        CORRIDORS,
        /** Few obstacles, far checkpoints and a battery that cannot do the tour without recharging. */
        BATTERY;

        /** @return its name on the command line */
        public String label() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** @return every kind's label */
        public static List<String> labels() {
            return Arrays.stream(values()).map(Kind::label).toList();
        }
    }

    private static final double ARENA_M = 5.0;
    private static final int MAX_DRAWS = 500;

    private final Kind kind;

    /** @param kind the kind of world to draw */
    public WorldGenerator(Kind kind) {
        this.kind = kind;
    }

    /**
     * @param seed   the sweep's seed
     * @param number the world's number, from 1
     * @return a valid, solvable world named {@code <kind>-<number>}, its noise seed drawn too
     * @throws IllegalStateException when no draw is solvable (not expected for the built-in kinds)
     */
    public WorldSpec world(long seed, int number) {
        SplittableRandom random = new SplittableRandom(seed * 1_000_003L + number * 7_919L + kind.ordinal());
        String name = String.format(Locale.ROOT, "%s-%03d", kind.label(), number);
        for (int draw = 0; draw < MAX_DRAWS; draw++) {
            WorldSpec candidate = draw(name, random);
            WorldSpec valid;
            try {
                valid = WorldFiles.parse(WorldJson.of(candidate), name); // the world file's own checks
            } catch (WorldValidationException e) {
                continue;
            }
            Solvability plan = Solvability.of(valid);
            if (!plan.solvable() || (kind == Kind.BATTERY && plan.recharges() == 0)) {
                continue;
            }
            // time for the tour at a third of top speed, the charging, and a margin
            double chargeS = plan.recharges() * valid.battery().rechargeTo() / valid.battery().rechargeRatePerS();
            double limit = Math.ceil((plan.lengthM() / (valid.robot().maxSpeedMps() / 3) + chargeS + 60) / 10) * 10;
            return new WorldSpec(name, valid.timeStepMs(), limit, valid.seed(), valid.arena(), valid.robot(),
                    valid.obstacles(), valid.checkpoints(), valid.checkpointRadiusM(), valid.rechargeStation(), valid.battery());
        }
        throw new IllegalStateException("no solvable " + kind.label() + " world in " + MAX_DRAWS + " draws");
    }

    private WorldSpec draw(String name, SplittableRandom random) {
        WorldSpec.Robot robot = new WorldSpec.Robot(0.0, -4.2, 90.0, WorldSpec.Robot.DEFAULT_RADIUS_M,
                WorldSpec.Robot.DEFAULT_MAX_SPEED_MPS, WorldSpec.Robot.DEFAULT_SENSOR_RANGE_M);
        List<Obstacle> obstacles = new ArrayList<>();
        List<WorldSpec.Checkpoint> checkpoints = new ArrayList<>();
        WorldSpec.RechargeStation station = new WorldSpec.RechargeStation(round(random.nextDouble(-3.2, -2.2)),
                round(random.nextDouble(-3.2, -2.2)), 0.35);
        WorldSpec.Battery battery = WorldSpec.Battery.DEFAULT;
        switch (kind) {
            case CLUTTERED -> clutter(random, robot, station, checkpoints, obstacles, 3 + random.nextInt(3), 10 + random.nextInt(7));
            case TRAPS -> traps(random, robot, checkpoints, obstacles);
            case CORRIDORS -> corridors(random, checkpoints, obstacles);
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
    private static void corridors(SplittableRandom random, List<WorldSpec.Checkpoint> checkpoints, List<Obstacle> obstacles) {
        int walls = 2 + random.nextInt(3);
        double bottom = -3.2;
        double top = 3.2;
        double spacing = (top - bottom) / (walls - 1);
        boolean gapRight = random.nextBoolean();
        for (int w = 0; w < walls; w++) {
            double y = round(bottom + w * spacing + random.nextDouble(-0.15, 0.15));
            double half = Math.sqrt(ARENA_M * ARENA_M - y * y); // the chord at this height
            double gap = random.nextDouble(1.0, 1.4);
            double from = gapRight ? -half - 0.3 : -half + gap;
            double to = gapRight ? half - gap : half + 0.3;
            obstacles.add(Obstacle.box(round((from + to) / 2), y, round(to - from), 0.2, 0.0));
            // in the lane below the wall, at the gap's end: the robot must reach it to get through
            double laneY = round(y - Math.min(0.8, spacing / 2));
            double laneHalf = Math.sqrt(ARENA_M * ARENA_M - laneY * laneY);
            double cx = gapRight ? laneHalf - gap / 2 - 0.4 : -laneHalf + gap / 2 + 0.4;
            checkpoints.add(new WorldSpec.Checkpoint(round(cx), laneY));
            gapRight = !gapRight;
        }
        double lastY = round(top + 0.8);
        checkpoints.add(new WorldSpec.Checkpoint(round(random.nextDouble(-1.5, 1.5)), Math.min(lastY, 4.0)));
    }

    private static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }
}
