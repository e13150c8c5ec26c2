package org.proactiverobotics.bench.mission;

import com.zaxxer.hikari.HikariDataSource;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import javax.sql.DataSource;
import org.proactiverobotics.bench.engine.Workload;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.Algorithm;

/**
 * Many robots, one database: N robots, each with its own simulation, controller and engine
 * (own robot_id, own scenarios, own world: the bundled worlds in turn, checkpoint order rotated
 * from the fifth robot on), all on one shared database, stepped flat out in rounds: a round is
 * one control step of every robot (sense, engine iteration, act, physics). The robots keep up
 * with a control step of 32 ms in real time while a round takes at most 32 ms; the figure is the
 * 95th percentile of the round's wall time over the measurement (after a warm-up). Missions
 * never end: each time a robot's engine has marked every checkpoint reached, a new lap starts
 * (outside the timed rounds).
 *
 * <p>Threads: with {@code --threads 1} (default) one thread steps the robots round-robin; with
 * T, the robots are split into T fixed groups stepped in parallel, the round ending when every
 * group is done; {@code --threads per-robot}: one thread per robot (a client-server database
 * spends most of a step waiting for round trips and commits, which threads overlap). The engines share one pool (as one engine process serving every robot would);
 * each robot has a pool of its own (as a robot process has).
 *
 * <p>A plain harness, not JMH: each N is one long run of a stateful system; the figure is a
 * distribution of round times against a deadline.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.mission.ManyRobots --robots auto
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.mission.ManyRobots --robots auto \
 *     --db 'jdbc:mariadb://127.0.0.1:3306/proactive_bench?user=root&amp;password='
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.mission.ManyRobots --robots auto --link direct
 * </pre>
 * Options: {@code --robots auto|N,N,...} (auto: double N from {@code --start N} (1) while the robots keep
 * up, then bisect),
 * {@code --threads T|per-robot} (1), {@code --link jdbc|direct} (jdbc), {@code --batches on|off} (on: a
 * thread's engines run their iterations as one batch, their tables read in one query and their
 * transactions committed as one, as an engine process serving several robots on a thread does, on a
 * database server; off: each reads and commits its own), {@code --db URL} (embedded H2, a
 * fresh in-memory database per N), {@code --user U --password P}, {@code --warmup-s S} (5),
 * {@code --measure-s S} (30), {@code --step-ms MS} (32).
 */
public final class ManyRobots {

    private ManyRobots() {
    }

    public static void main(String[] args) throws Exception {
        Workload.quietLogs();
        Map<String, String> opt = LongRun.Args.parse(args);
        Config cfg = new Config(opt);
        System.out.printf(Locale.ROOT, "ManyRobots link=%s db=%s threads=%s batches=%s warmup=%ds measure=%ds step=%dms load=%s%n",
                cfg.direct ? "direct" : "jdbc", cfg.direct ? "-" : LongRun.Args.kind(cfg.url(1)), cfg.threads > 0 ? String.valueOf(cfg.threads) : "per-robot",
                cfg.batches ? "on" : "off", cfg.warmupS, cfg.measureS, cfg.stepMs, LongRun.Args.load());
        System.out.println("| robots | rounds | round mean ms | p50 | p95 | p99 | max | ms / robot-step (engine / robot / physics) | keeps up | laps | collisions | load |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|");
        String robots = opt.getOrDefault("robots", "auto");
        if (!robots.equals("auto")) {
            for (String n : robots.split(",")) {
                run(cfg, Integer.parseInt(n.trim()));
            }
            return;
        }
        int good = 0;
        int bad = -1;
        for (int n = Integer.parseInt(opt.getOrDefault("start", "1")); bad < 0; n *= 2) {
            if (run(cfg, n)) {
                good = n;
            } else {
                bad = n;
            }
        }
        while (bad - good > Math.max(1, good / 8)) {
            int n = (good + bad) / 2;
            if (run(cfg, n)) {
                good = n;
            } else {
                bad = n;
            }
        }
        System.out.printf(Locale.ROOT, "LARGEST robots keeping up with %d ms: %d (%d did not)%n", cfg.stepMs, good, bad);
    }

    /** @return whether n robots kept up */
    private static boolean run(Config cfg, int n) throws Exception {
        List<Rig> rigs = new ArrayList<>();
        HikariDataSource enginePool = null;
        int threads = cfg.threads > 0 ? cfg.threads : n;
        ExecutorService pool = threads > 1 ? Executors.newFixedThreadPool(threads) : null;
        try {
            if (!cfg.direct) {
                var config = Databases.allowMultiStatements(Databases.config(cfg.url(n), cfg.user, cfg.password), cfg.url(n));
                config.setMaximumPoolSize(Math.max(4, threads + 1));
                enginePool = new HikariDataSource(config);
            }
            for (int i = 0; i < n; i++) {
                rigs.add(cfg.direct ? Rig.direct(Worlds.forRobot(i), i + 1, Algorithm.LAZY)
                        : Rig.jdbc(Worlds.forRobot(i), i + 1, enginePool, cfg.url(n), cfg.user, cfg.password));
            }
            List<List<Rig>> shares = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                List<Rig> share = new ArrayList<>();
                for (int i = t; i < rigs.size(); i += threads) {
                    share.add(rigs.get(i));
                }
                shares.add(share);
            }
            DataSource batchPool = cfg.batches ? enginePool : null;
            List<Callable<Void>> groups = new ArrayList<>();
            for (List<Rig> share : shares) {
                groups.add(() -> {
                    stepShare(share, batchPool);
                    return null;
                });
            }
            // The first round robot by robot: a fresh engine's first state save inserts its engine_state
            // row, and on MariaDB concurrent first saves deadlock (UPDATE of a missing row, then INSERT).
            for (Rig rig : rigs) {
                rig.step();
            }
            long[] times = new long[1 << 16];
            int rounds = 0;
            long warmupEnd = System.nanoTime() + cfg.warmupS * 1_000_000_000L;
            long end = warmupEnd + cfg.measureS * 1_000_000_000L;
            boolean measuring = false;
            long round = 0;
            while (true) {
                long now = System.nanoTime();
                if (!measuring && now >= warmupEnd) {
                    measuring = true;
                    rigs.forEach(Rig::resetTimes);
                }
                if (now >= end) {
                    break;
                }
                long t0 = System.nanoTime();
                if (pool == null) {
                    stepShare(rigs, batchPool);
                } else {
                    for (Future<Void> f : pool.invokeAll(groups)) {
                        f.get();
                    }
                }
                long ns = System.nanoTime() - t0;
                if (measuring) {
                    if (rounds == times.length) {
                        times = Arrays.copyOf(times, rounds * 2);
                    }
                    times[rounds++] = ns;
                }
                if (++round % 50 == 0) {
                    for (Rig rig : rigs) {
                        rig.rearm();
                    }
                }
            }
            long[] sorted = Arrays.copyOf(times, rounds);
            Arrays.sort(sorted);
            double mean = Arrays.stream(sorted).average().orElse(Double.NaN) / 1e6;
            double p95 = pct(sorted, 0.95);
            long robotSteps = rigs.stream().mapToLong(r -> r.steps).sum();
            double engine = rigs.stream().mapToLong(r -> r.engineNs).sum() / 1e6 / robotSteps;
            double robot = rigs.stream().mapToLong(r -> r.robotNs).sum() / 1e6 / robotSteps;
            double physics = rigs.stream().mapToLong(r -> r.physicsNs).sum() / 1e6 / robotSteps;
            long laps = rigs.stream().mapToLong(r -> r.lapsDone).sum();
            long collisions = rigs.stream().mapToLong(r -> r.truth().collisions()).sum();
            long failed = rigs.stream().mapToLong(r -> r.failedIterations).sum();
            rigs.stream().filter(r -> r.lastFailure != null).findFirst()
                    .ifPresent(r -> System.out.println("  failed iterations: " + failed + ", e.g. robot " + r.robotId + ": " + r.lastFailure));
            boolean keepsUp = p95 <= cfg.stepMs;
            System.out.printf(Locale.ROOT,
                    "| %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.3f (%.3f / %.3f / %.3f) | %s | %d | %d | %s |%n", n,
                    rounds, mean, pct(sorted, 0.5), p95, pct(sorted, 0.99), sorted[rounds - 1] / 1e6,
                    engine + robot + physics, engine, robot, physics, keepsUp ? "yes" : "no", laps, collisions,
                    LongRun.Args.load());
            return keepsUp;
        } finally {
            for (Rig rig : rigs) {
                rig.close();
            }
            if (enginePool != null) {
                if (cfg.url(n).startsWith("jdbc:h2:mem:")) {
                    try (var c = enginePool.getConnection(); var s = c.createStatement()) {
                        s.execute("DROP ALL OBJECTS");
                    }
                }
                enginePool.close();
            }
            if (pool != null) {
                pool.shutdownNow();
            }
        }
    }

    /** One step of each robot of a thread's share: the engines' iterations as one batch, or each on its own. */
    private static void stepShare(List<Rig> share, DataSource batchPool) {
        if (batchPool != null && share.size() > 1) {
            Rig.stepAll(share, batchPool);
        } else {
            for (Rig rig : share) {
                rig.step();
            }
        }
    }

    private static double pct(long[] sorted, double p) {
        return sorted[Math.min(sorted.length - 1, (int) (sorted.length * p))] / 1e6;
    }

    private static final class Config {
        final boolean direct;
        final String db;
        final String user;
        final String password;
        final int threads;
        final int warmupS;
        final int measureS;
        final int stepMs;
        final boolean batches;

        Config(Map<String, String> opt) {
            direct = opt.getOrDefault("link", "jdbc").equals("direct");
            db = opt.get("db");
            boolean h2 = db == null || db.startsWith("jdbc:h2:");
            user = opt.getOrDefault("user", h2 ? "sa" : null);
            password = opt.getOrDefault("password", h2 ? "" : null);
            String t = opt.getOrDefault("threads", "1");
            threads = t.equals("per-robot") ? 0 : Integer.parseInt(t);
            warmupS = Integer.parseInt(opt.getOrDefault("warmup-s", "5"));
            measureS = Integer.parseInt(opt.getOrDefault("measure-s", "30"));
            stepMs = Integer.parseInt(opt.getOrDefault("step-ms", "32"));
            batches = !direct && !opt.getOrDefault("batches", "on").equals("off");
        }

        /** The database of a run of n robots: the given one, or a fresh in-memory H2 per n. */
        String url(int n) {
            return db != null ? db : Databases.embeddedH2Url("bench_many_" + n);
        }
    }
}
