package org.proactiverobotics.bench.mission;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.proactiverobotics.app.link.DirectEngineTables;
import org.proactiverobotics.app.link.DirectLink;
import org.proactiverobotics.bench.engine.Workload;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.robot.RobotConfig;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * N robots in one world (issue 34): one {@link Simulation} with every robot, each robot with its full engine (map,
 * routes, every built-in scenario) and controller over the in-process direct link, stepped as {@code run} steps a
 * fleet: every robot senses, every engine iterates (on {@code --threads} threads, as {@code run --threads}),
 * every robot acts, the world steps once. Flat out. The world: a rectangle of 4 m cells, a robot at the centre of each, a pillar at each inner corner, each
 * robot's mission a square lap round its cell's centre, started again each time its engine has reached every
 * checkpoint (so no mission ends); neighbours' laps come within about a metre of each other.
 * <p>
 * Per N: the real-time factor (simulated time per wall time) over the measurement, the mean wall time per world
 * step by part (physics: dyn4j and the rays; engine: the N iterations; robot: the N controllers' sense and act),
 * and the heap per robot after the warm-up (used heap after a GC, less that before the robots were built).
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.mission.OneWorld --robots 10,25,50,100
 * </pre>
 * Options: {@code --robots N,N,...} (10,25,50,100), {@code --warmup-s S} (simulated, 10), {@code --measure-s S}
 * (simulated, 30), {@code --threads T} (1).
 */
public final class OneWorld {

    private static final double CELL_M = 4.0;
    private static final double LAP_HALF_M = 1.2;

    private OneWorld() {
    }

    public static void main(String[] args) {
        Workload.quietLogs();
        Map<String, String> opt = LongRun.Args.parse(args);
        double warmupS = Double.parseDouble(opt.getOrDefault("warmup-s", "10"));
        double measureS = Double.parseDouble(opt.getOrDefault("measure-s", "30"));
        int threads = Integer.parseInt(opt.getOrDefault("threads", "1"));
        System.out.printf(Locale.ROOT, "OneWorld link=direct threads=%d warmup=%.0fs measure=%.0fs (simulated) load=%s%n",
                threads, warmupS, measureS, LongRun.Args.load());
        System.out.println("| robots | steps | real-time factor | ms / step | physics | engines | robots | "
                + "engine ms / robot-step | heap / robot MB | robot collisions | laps |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|");
        for (String n : opt.getOrDefault("robots", "10,25,50,100").split(",")) {
            run(Integer.parseInt(n.trim()), warmupS, measureS, threads);
        }
        System.out.printf(Locale.ROOT, "load=%s%n", LongRun.Args.load());
    }

    /** A world of {@code n} cells, a robot in each. */
    static WorldSpec world(int n) {
        int cols = (int) Math.ceil(Math.sqrt(n));
        int rows = (n + cols - 1) / cols;
        double width = cols * CELL_M;
        double height = rows * CELL_M;
        List<WorldSpec.RobotEntry> robots = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double cx = -width / 2 + CELL_M * (i % cols + 0.5);
            double cy = -height / 2 + CELL_M * (i / cols + 0.5);
            double h = LAP_HALF_M;
            robots.add(new WorldSpec.RobotEntry(i + 1, new WorldSpec.Robot(cx - h, cy - h, 0.0, 0.12, 0.5, 1.0),
                    List.of(new WorldSpec.Checkpoint(cx + h, cy - h), new WorldSpec.Checkpoint(cx + h, cy + h),
                            new WorldSpec.Checkpoint(cx - h, cy + h), new WorldSpec.Checkpoint(cx - h, cy - h))));
        }
        List<WorldSpec.Obstacle> pillars = new ArrayList<>();
        for (int c = 1; c < cols; c++) {
            for (int r = 1; r < rows; r++) {
                pillars.add(WorldSpec.Obstacle.circle(-width / 2 + c * CELL_M, -height / 2 + r * CELL_M, 0.2));
            }
        }
        return WorldSpec.fleet("one-world-" + n, 32, 100_000, 1, WorldSpec.Arena.rectangle(width, height, 0, 0), robots,
                pillars, 0.25, List.of(new WorldSpec.RechargeStation(0, 0, 0.35)),
                new WorldSpec.Battery(100.0, 0.0, 100.0, 10.0)); // no drain: laps go on for ever
    }

    private static void run(int n, double warmupS, double measureS, int threads) {
        ExecutorService pool = threads > 1 ? Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "engines");
            t.setDaemon(true);
            return t;
        }) : null;
        long baseHeap = usedHeapAfterGc();
        WorldSpec world = world(n);
        Simulation sim = new Simulation(world);
        DirectLink link = new DirectLink();
        List<RobotEngine> engines = new ArrayList<>();
        List<Rig.Laps> laps = new ArrayList<>();
        List<ProactiveController> controllers = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int id = world.robots().get(i).id();
            DirectEngineTables tables = link.engine(id);
            Rig.Laps lap = new Rig.Laps(tables);
            EngineTables wired = new EngineTables(tables, tables, lap, tables, tables, tables::pruneHistory, tables);
            WorldSpec.Robot r = world.robots().get(i).robot();
            RobotEngine engine = RobotEngine.builder().tables(wired, StateStore.none()).robotId(id)
                    .drive(new DriveProfile(r.maxSpeedMps(), 2 * r.radiusM())).build();
            engine.startFresh();
            engine.writeStrategy(Strategy.named(Strategy.SAFETY_FIRST));
            engines.add(engine);
            laps.add(lap);
            controllers.add(new ProactiveController(sim, i, link, RobotConfig.defaults(id)));
        }
        long warmupSteps = Math.round(warmupS * 1000 / world.timeStepMs());
        long measureSteps = Math.round(measureS * 1000 / world.timeStepMs());
        long[] ns = new long[3];
        for (long s = 0; s < warmupSteps; s++) {
            step(sim, engines, controllers, ns, pool);
        }
        long heapPerRobot = (usedHeapAfterGc() - baseHeap) / n;
        ns[0] = ns[1] = ns[2] = 0;
        long start = System.nanoTime();
        for (long s = 0; s < measureSteps; s++) {
            step(sim, engines, controllers, ns, pool);
        }
        double wallS = (System.nanoTime() - start) / 1e9;
        int robotCollisions = 0;
        long lapsDone = 0;
        for (int i = 0; i < n; i++) {
            robotCollisions += sim.groundTruth(i).robotCollisions();
            lapsDone += laps.get(i).laps;
        }
        double perStep = 1e6 * measureSteps;
        System.out.printf(Locale.ROOT, "| %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.3f | %.1f | %d | %d |%n", n,
                measureSteps, measureS / wallS, wallS * 1000 / measureSteps, ns[0] / perStep, ns[1] / perStep,
                ns[2] / perStep, ns[1] / perStep / n, heapPerRobot / 1e6, robotCollisions, lapsDone);
        for (ProactiveController c : controllers) {
            c.close();
        }
        if (pool != null) {
            pool.shutdownNow();
        }
    }

    /** One world step of every robot; adds physics, engine and robot wall time to {@code ns}. */
    private static void step(Simulation sim, List<RobotEngine> engines, List<ProactiveController> controllers, long[] ns,
                             ExecutorService pool) {
        long t0 = System.nanoTime();
        for (ProactiveController c : controllers) {
            c.sense();
        }
        long t1 = System.nanoTime();
        if (pool == null) {
            for (RobotEngine e : engines) {
                e.iterate();
            }
        } else {
            List<Future<?>> running = new ArrayList<>(engines.size());
            for (RobotEngine e : engines) {
                running.add(pool.submit(() -> { e.iterate(); }));
            }
            try {
                for (Future<?> f : running) {
                    f.get();
                }
            } catch (InterruptedException | ExecutionException ex) {
                throw new IllegalStateException(ex);
            }
        }
        long t2 = System.nanoTime();
        for (ProactiveController c : controllers) {
            c.act();
        }
        long t3 = System.nanoTime();
        sim.step();
        long t4 = System.nanoTime();
        ns[0] += t4 - t3;
        ns[1] += t2 - t1;
        ns[2] += (t1 - t0) + (t3 - t2);
    }

    private static long usedHeapAfterGc() {
        Runtime rt = Runtime.getRuntime();
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        return rt.totalMemory() - rt.freeMemory();
    }
}
