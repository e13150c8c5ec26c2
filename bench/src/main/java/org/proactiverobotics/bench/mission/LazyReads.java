package org.proactiverobotics.bench.mission;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Proxy;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;
import javax.sql.DataSource;
import org.proactiverobotics.bench.engine.Workload;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.Algorithm;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Lazy versus standard evaluation: database reads per engine iteration, counted at the JDBC
 * level ({@link CountingDataSource} under the engine's pool: every executeQuery is one read).
 *
 * <p>Part 1, a synthetic workload on embedded H2: N self-cloning rules; a rule's guard data is
 * one read (its flag), its condition data another (its value); only every k-th rule's flag is
 * set, so (k-1)/k of the guards fail. The standard algorithm reads both for every rule, the lazy
 * one the second only for the rules whose guard held. No state store (only the rules' reads).
 *
 * <p>Part 2, the robot's real scenarios over whole missions (each bundled world, lockstep as
 * {@code Mission}, the production {@code RobotEngine} wiring: one transaction per iteration, state
 * saved, history pruned), once per algorithm (lazy is what every command runs). Only the engine
 * side's statements are counted (state store included); the robot has a pool of its own.
 *
 * <p>A plain harness, not JMH: the figure is a count, deterministic; the times beside it are
 * means after a warm-up, for orientation.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.mission.LazyReads
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.mission.LazyReads --part missions \
 *     --db 'jdbc:mariadb://127.0.0.1:3306/proactive_bench?user=root&amp;password='
 * </pre>
 * Options: {@code --part synthetic|missions|both} (both), {@code --rules N} (100),
 * {@code --iterations N} (2000, after as many warm-up iterations), {@code --db URL} for part 2
 * (embedded H2), {@code --statements true} to list part 2's statements per algorithm.
 */
public final class LazyReads {

    private LazyReads() {
    }

    public static void main(String[] args) throws Exception {
        Workload.quietLogs();
        Map<String, String> opt = LongRun.Args.parse(args);
        String part = opt.getOrDefault("part", "both");
        System.out.println("LazyReads load=" + LongRun.Args.load());
        if (!part.equals("missions")) {
            synthetic(Integer.parseInt(opt.getOrDefault("rules", "100")),
                    Integer.parseInt(opt.getOrDefault("iterations", "2000")));
        }
        if (!part.equals("synthetic")) {
            missions(opt.get("db"), Boolean.parseBoolean(opt.getOrDefault("statements", "false")));
        }
    }

    // ------------------------------------------------------------------ part 1

    private static void synthetic(int rules, int iterations) throws SQLException {
        System.out.println();
        System.out.println("| algorithm | rules | guards failing | DB reads / iteration | reads / rule | us / iteration |");
        System.out.println("|---|---|---|---|---|---|");
        for (int every : new int[] {10, 2, 1}) {
            for (Algorithm algorithm : Algorithm.values()) {
                try (HikariDataSource pool = Databases.pool(Databases.embeddedH2Url("bench_lazy_synthetic"), "sa", "")) {
                    seed(pool, rules, every);
                    CountingDataSource counting = new CountingDataSource(pool);
                    ProactiveEngine engine = ProactiveEngine.builder().algorithm(algorithm).store(StateStore.none())
                            .service(DataSource.class, counting).build();
                    List<Rule> all = new ArrayList<>();
                    for (int i = 0; i < rules; i++) {
                        all.add(new FlaggedRule(i));
                    }
                    engine.startFresh(all.toArray(Rule[]::new));
                    for (int i = 0; i < iterations; i++) {
                        engine.runIteration();
                    }
                    counting.reset();
                    long t0 = System.nanoTime();
                    for (int i = 0; i < iterations; i++) {
                        engine.runIteration();
                    }
                    long ns = System.nanoTime() - t0;
                    double reads = (double) counting.reads() / iterations;
                    System.out.printf(Locale.ROOT, "| %s | %d | %d %% | %.1f | %.2f | %.0f |%n", algorithm, rules,
                            Math.round(100.0 * (every - 1) / every), reads, reads / rules, ns / 1e3 / iterations);
                }
            }
        }
        System.out.println("load=" + LongRun.Args.load());
    }

    private static void seed(DataSource pool, int rules, int every) throws SQLException {
        try (Connection c = pool.getConnection(); Statement s = c.createStatement()) {
            s.execute("DROP TABLE IF EXISTS bench_flags");
            s.execute("DROP TABLE IF EXISTS bench_values");
            s.execute("CREATE TABLE bench_flags (k INT PRIMARY KEY, v INT NOT NULL)");
            s.execute("CREATE TABLE bench_values (k INT PRIMARY KEY, v BIGINT NOT NULL)");
            try (PreparedStatement f = c.prepareStatement("INSERT INTO bench_flags VALUES (?, ?)");
                 PreparedStatement v = c.prepareStatement("INSERT INTO bench_values VALUES (?, ?)")) {
                for (int i = 0; i < rules; i++) {
                    f.setInt(1, i);
                    f.setInt(2, i % every == 0 ? 1 : 0);
                    f.executeUpdate();
                    v.setInt(1, i);
                    v.setLong(2, i);
                    v.executeUpdate();
                }
            }
        }
    }

    /** Guard: its flag is set (one read). Condition: its value is not negative (another read). */
    static final class FlaggedRule extends Rule {
        private int key;
        private transient boolean flag;
        private transient long value;
        private transient long actions;

        @SuppressWarnings("unused")
        private FlaggedRule() {
        }

        FlaggedRule(int key) {
            this.key = key;
        }

        @Override
        public String scenario() {
            return "Bench";
        }

        @Override
        protected void acquireGuardData(RuleContext ctx) throws SQLException {
            flag = readInt(ctx, "SELECT v FROM bench_flags WHERE k = ?") != 0;
        }

        @Override
        protected void acquireConditionData(RuleContext ctx) throws SQLException {
            value = readInt(ctx, "SELECT v FROM bench_values WHERE k = ?");
        }

        private long readInt(RuleContext ctx, String sql) throws SQLException {
            try (Connection c = ctx.service(DataSource.class).getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
                ps.setInt(1, key);
                try (ResultSet rs = ps.executeQuery()) {
                    return rs.next() ? rs.getLong(1) : 0;
                }
            }
        }

        @Override
        protected boolean activationGuards(RuleContext ctx) {
            return flag;
        }

        @Override
        protected boolean conditions(RuleContext ctx) {
            return value >= 0;
        }

        @Override
        protected void actions(RuleContext ctx) {
            actions++;
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }

    // ------------------------------------------------------------------ part 2

    private static void missions(String url, boolean statements) throws Exception {
        System.out.println();
        System.out.println("| world | engine | outcome | steps | rules' table reads / iteration | DB reads / iteration"
                + " | DB writes / iteration | engine ms / iteration |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        for (String name : Worlds.BUNDLED) {
            for (String variant : new String[] {"STANDARD", "LAZY"}) {
                String dbUrl = url != null ? url : Databases.embeddedH2Url("bench_lazy_" + name.replace('-', '_') + "_" + variant);
                boolean h2 = dbUrl.startsWith("jdbc:h2:");
                try (HikariDataSource pool = Databases.pool(dbUrl, h2 ? "sa" : null, h2 ? "" : null)) {
                    CountingDataSource counting = new CountingDataSource(pool);
                    WorldSpec world = WorldFiles.bundled(name);
                    String user = h2 ? "sa" : null;
                    String password = h2 ? "" : null;
                    LongAdder tableReads = new LongAdder();
                    try (Rig rig = Rig.jdbc(world, 1, counting, dbUrl, user, password, Algorithm.valueOf(variant),
                            t -> countingReads(t, tableReads))) {
                        counting.reset();
                        tableReads.reset();
                        GroundTruth truth = rig.truth();
                        String outcome;
                        while (true) {
                            rig.step();
                            if (truth.checkpointsReached() == truth.checkpointsTotal()) {
                                outcome = "accomplished";
                                break;
                            }
                            if (truth.batteryPct() <= 0.0) {
                                outcome = "battery depleted";
                                break;
                            }
                            if (rig.sim.timeLimitReached()) {
                                outcome = "time limit";
                                break;
                            }
                        }
                        System.out.printf(Locale.ROOT, "| %s | %s | %s | %d | %.2f | %.2f | %.2f | %.3f |%n", name, variant,
                                outcome, rig.steps, tableReads.doubleValue() / rig.steps, (double) counting.reads() / rig.steps, (double) counting.writes() / rig.steps,
                                rig.engineNs / 1e6 / rig.steps);
                        if (statements) {
                            counting.bySql().forEach((sql, n) -> System.out.printf(Locale.ROOT, "    %8.3f  %s%n",
                                    (double) n / rig.steps, sql.length() > 150 ? sql.substring(0, 150) + "..." : sql));
                        }
                    }
                }
            }
        }
        System.out.println("load=" + LongRun.Args.load());
    }

    /**
     * The rules' reads of the tables, counted above the communication layer: what lazy evaluation
     * saves now that the database is read once per iteration (a snapshot) whatever the rules ask.
     */
    static EngineTables countingReads(EngineTables t, LongAdder reads) {
        return new EngineTables(countingReads(SensorReadings.class, t.readings(), reads),
                countingReads(SensorRequests.class, t.requests(), reads), countingReads(MissionTables.class, t.mission(), reads),
                countingReads(StrategyTable.class, t.strategy(), reads), t.comments(), t.pruneHistory(),
                countingReads(PoseEstimateTable.class, t.poses(), reads));
    }

    /** A proxy that counts the calls that return something (the reads) and passes every call on. */
    private static <T> T countingReads(Class<T> type, T target, LongAdder reads) {
        return type.cast(Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] {type}, (proxy, method, args) -> {
            if (method.getReturnType() != void.class && method.getDeclaringClass() != Object.class) {
                reads.increment();
            }
            try {
                return method.invoke(target, args);
            } catch (InvocationTargetException e) {
                throw e.getCause();
            }
        }));
    }
}
