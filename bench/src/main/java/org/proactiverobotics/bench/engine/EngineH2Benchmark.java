package org.proactiverobotics.bench.engine;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.SQLException;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.persistence.JdbcStateStore;

/**
 * Engine iterations over n self-cloning rules with the state saved to embedded H2 at the end of
 * every iteration (one transaction: nextQueue rewritten, n rows). For n = 1 000 000 run it with
 * fewer iterations (-wi 1 -i 2): one iteration takes seconds.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Fork(value = 1, jvmArgsAppend = "-Xmx6g")
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 3, time = 1)
public class EngineH2Benchmark {

    @Param({"10", "1000", "1000000"})
    int n;

    private HikariDataSource dataSource;
    private ProactiveEngine engine;

    @Setup(Level.Trial)
    public void setUp() throws SQLException {
        Workload.quietLogs();
        dataSource = Databases.pool(Databases.embeddedH2Url("bench_engine_" + n), "sa", "");
        Schema.apply(dataSource);
        engine = ProactiveEngine.builder().store(new JdbcStateStore(dataSource)).build();
        engine.startFresh(CountingRule.many(n));
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        dataSource.close();
    }

    /** One engine iteration: n rules run and regenerated, then nextQueue saved. */
    @Benchmark
    public int iteration(RuleCounter counter) {
        int run = engine.runIteration().rulesRun();
        counter.rules += run;
        return run;
    }
}
