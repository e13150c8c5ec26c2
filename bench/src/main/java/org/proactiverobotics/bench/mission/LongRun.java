package org.proactiverobotics.bench.mission;

import com.zaxxer.hikari.HikariDataSource;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.proactiverobotics.bench.engine.Workload;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.WorldFiles;

/**
 * A mission that never ends, for the time of a control step near step 1 000, 10 000, 100 000
 * and 1 000 000 (retention must keep it flat) and the heap. The reference world without a time
 * limit; each time the engine has marked every checkpoint reached, the flags are reset in the
 * database (outside the timed step) and the robot starts a new lap, recharging when its battery
 * asks. One robot, lockstep as {@code Mission}: sense, engine iteration (the engine process's
 * wiring: one transaction, history pruned every 100 iterations), act, physics step; the robot
 * prunes its readings with the default retention policy.
 *
 * <p>A plain harness, not JMH: the measurement is one long run whose state (tables, heap) is
 * what is measured; JMH's repeated iterations would measure the start again and again.
 *
 * <pre>
 * java -Xmx512m -Xlog:gc:file=/tmp/longrun-gc.log -cp bench/target/benchmarks.jar \
 *     org.proactiverobotics.bench.mission.LongRun --steps 1000000
 * </pre>
 * Options: {@code --steps N} (1 000 000), {@code --window W} (500: a mark's figure is the mean of
 * the W steps ending at it), {@code --report-every N} (10 000: a progress line, after a forced GC
 * to measure the live heap), {@code --db URL --user U --password P} (embedded H2),
 * {@code --world NAME} (reference-arena).
 */
public final class LongRun {

    private LongRun() {
    }

    public static void main(String[] args) throws Exception {
        Workload.quietLogs();
        Map<String, String> opt = Args.parse(args);
        long steps = Long.parseLong(opt.getOrDefault("steps", "1000000"));
        int window = Integer.parseInt(opt.getOrDefault("window", "500"));
        long reportEvery = Long.parseLong(opt.getOrDefault("report-every", "10000"));
        String url = opt.getOrDefault("db", Databases.embeddedH2Url("bench_longrun"));
        String user = opt.getOrDefault("user", url.startsWith("jdbc:h2:") ? "sa" : null);
        String password = opt.getOrDefault("password", url.startsWith("jdbc:h2:") ? "" : null);
        String worldName = opt.getOrDefault("world", "reference-arena");
        Set<Long> marks = new TreeSet<>();
        for (long m = 1000; m <= steps; m *= 10) {
            marks.add(m);
        }
        marks.add(steps);

        System.out.printf(Locale.ROOT, "LongRun world=%s db=%s steps=%d window=%d maxHeap=%dMB load=%s%n", worldName,
                Args.kind(url), steps, window, Runtime.getRuntime().maxMemory() >> 20, Args.load());
        long[] times = new long[window];
        long peakLive = 0;
        long blockStart = System.nanoTime();
        long sinceReportNs = 0;
        long sinceReportSteps = 0;
        long start = System.nanoTime();
        try (HikariDataSource pool = Databases.multiStatementPool(url, user, password);
             Rig rig = Rig.jdbc(Worlds.endless(WorldFiles.bundled(worldName)), 1, pool, url, user, password)) {
            GroundTruth truth = rig.truth();
            for (long k = 1; k <= steps; k++) {
                long ns = rig.step();
                times[(int) ((k - 1) % window)] = ns;
                sinceReportNs += ns;
                sinceReportSteps++;
                if (k % 50 == 0) {
                    rig.rearm();
                }
                if (marks.contains(k)) {
                    long[] w = Arrays.copyOf(times, (int) Math.min(window, k));
                    Arrays.sort(w);
                    double mean = Arrays.stream(w).average().orElse(0) / 1e6;
                    System.out.printf(Locale.ROOT,
                            "MARK step=%d window=%d mean=%.3fms p50=%.3fms p99=%.3fms max=%.3fms load=%s%n", k,
                            w.length, mean, w[w.length / 2] / 1e6, w[(int) (w.length * 0.99)] / 1e6,
                            w[w.length - 1] / 1e6, Args.load());
                }
                if (k % reportEvery == 0 || k == steps) {
                    long heapPeak = heapPeakBytes();
                    System.gc();
                    long live = Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory();
                    peakLive = Math.max(peakLive, live);
                    StringBuilder line = new StringBuilder(String.format(Locale.ROOT,
                            "PROGRESS step=%d wall=%.0fs meanSinceLast=%.3fms engine=%.3f robot=%.3f physics=%.3f"
                                    + " liveHeap=%.1fMB peakHeapUsed=%.1fMB laps=%d recharges=%d collisions=%d"
                                    + " battery=%.1f distance=%.0fm load=%s",
                            k, (System.nanoTime() - start) / 1e9, sinceReportNs / 1e6 / sinceReportSteps,
                            rig.engineNs / 1e6 / rig.steps, rig.robotNs / 1e6 / rig.steps, rig.physicsNs / 1e6 / rig.steps,
                            live / 1048576.0, heapPeak / 1048576.0, rig.lapsDone, truth.recharges(), truth.collisions(),
                            truth.batteryPct(), truth.distanceM(), Args.load()));
                    if (k % (reportEvery * 10) == 0 || k == steps) {
                        line.append(" rows=").append(Rig.rowCounts(pool));
                    }
                    System.out.println(line);
                    rig.resetTimes();
                    sinceReportNs = 0;
                    sinceReportSteps = 0;
                }
            }
            System.out.printf(Locale.ROOT, "DONE steps=%d wall=%.0fs peakLiveHeap=%.1fMB peakHeapUsed=%.1fMB rows=%s%n",
                    steps, (System.nanoTime() - start) / 1e9, peakLive / 1048576.0, heapPeakBytes() / 1048576.0,
                    Rig.rowCounts(pool));
        }
    }

    /** The sum of the heap pools' peak usage since the start. */
    static long heapPeakBytes() {
        long sum = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                sum += pool.getPeakUsage().getUsed();
            }
        }
        return sum;
    }

    /** Tiny option parsing shared by the mission harnesses: {@code --key value} pairs. */
    static final class Args {
        private Args() {
        }

        static Map<String, String> parse(String[] args) {
            Map<String, String> m = new HashMap<>();
            for (int i = 0; i < args.length; i++) {
                if (!args[i].startsWith("--") || i + 1 >= args.length) {
                    throw new IllegalArgumentException("expected --key value pairs, got: " + String.join(" ", args));
                }
                m.put(args[i].substring(2), args[++i]);
            }
            return m;
        }

        static String kind(String url) {
            String rest = url.substring(5);
            return rest.substring(0, rest.indexOf(':'));
        }

        /** @return the 1-minute load average */
        static String load() {
            return String.format(Locale.ROOT, "%.2f", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
    }
}
