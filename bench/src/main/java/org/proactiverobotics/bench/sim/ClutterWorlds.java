package org.proactiverobotics.bench.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.proactiverobotics.bench.mission.BigFloor;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Worlds for the simulator benchmark: the bundled reference arena, and generated arenas with a given number
 * of obstacles at a constant density (one per ~4 m²), so that the robot meets about as much clutter in each
 * and only the obstacle count grows. The battery never drains, so the robot drives for the whole run.
 */
final class ClutterWorlds {

    /** Square metres of arena per obstacle. */
    private static final double AREA_PER_OBSTACLE_M2 = 4.0;
    /** Gap kept between obstacles and around the start, metres. */
    private static final double GAP_M = 0.6;

    private ClutterWorlds() {
    }

    /** @param which {@code reference}, an obstacle count, or a building floor {@code floorWxH} in metres (BigFloor, seed 1) */
    static WorldSpec of(String which) {
        WorldSpec reference = WorldFiles.bundled(WorldFiles.DEFAULT_WORLD);
        WorldSpec.Battery endless = new WorldSpec.Battery(100, 0.0, 100, 10);
        if ("reference".equals(which)) {
            return reference.withBattery(endless);
        }
        if (which.startsWith("floor")) {
            String[] size = which.substring("floor".length()).split("x");
            return BigFloor.world(Double.parseDouble(size[0]), Double.parseDouble(size[1]), 1).withBattery(endless);
        }
        return cluttered(Integer.parseInt(which), endless);
    }

    /** Rejection-samples n circles and boxes (deterministic), keeping the gaps a robot needs. */
    static WorldSpec cluttered(int n, WorldSpec.Battery battery) {
        double radius = Math.sqrt(n * AREA_PER_OBSTACLE_M2 / Math.PI) + 2.0;
        SplittableRandom rnd = new SplittableRandom(42);
        List<WorldSpec.Obstacle> obstacles = new ArrayList<>(n);
        List<double[]> discs = new ArrayList<>(n); // bounding discs: x, y, r
        while (obstacles.size() < n) {
            double size = 0.15 + 0.3 * rnd.nextDouble();
            double rho = (radius - size - GAP_M) * Math.sqrt(rnd.nextDouble());
            double phi = 2 * Math.PI * rnd.nextDouble();
            double x = rho * Math.cos(phi);
            double y = rho * Math.sin(phi);
            boolean box = rnd.nextBoolean();
            double w = box ? 2 * size : 0;
            double h = box ? size : 0;
            double bound = box ? Math.hypot(w, h) / 2 : size;
            if (Math.hypot(x, y) < bound + GAP_M + 0.12 || overlaps(discs, x, y, bound)) {
                continue;
            }
            discs.add(new double[] {x, y, bound});
            obstacles.add(box ? WorldSpec.Obstacle.box(x, y, w, h, 180 * rnd.nextDouble())
                    : WorldSpec.Obstacle.circle(x, y, size));
        }
        return new WorldSpec("clutter-" + n, 32, 600, 1, new WorldSpec.Arena(radius),
                new WorldSpec.Robot(0, 0, 90, 0.12, 0.5, 1.0), obstacles, List.of(new WorldSpec.Checkpoint(0, 1)), 0.25,
                new WorldSpec.RechargeStation(0, -1, 0.35), battery);
    }

    private static boolean overlaps(List<double[]> discs, double x, double y, double r) {
        for (double[] d : discs) {
            if (Math.hypot(x - d[0], y - d[1]) < r + d[2] + GAP_M) {
                return true;
            }
        }
        return false;
    }
}
