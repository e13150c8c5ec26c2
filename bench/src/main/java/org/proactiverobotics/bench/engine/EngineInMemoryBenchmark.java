package org.proactiverobotics.bench.engine;

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
import org.openjdk.jmh.annotations.Warmup;
import org.proactiverobotics.engine.Algorithm;
import org.proactiverobotics.engine.ProactiveEngine;

/** Engine iterations over a queue of n self-cloning rules, no persistence, no listener. */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Fork(value = 1, jvmArgsAppend = "-Xmx4g")
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 3, time = 1)
public class EngineInMemoryBenchmark {

    @Param({"10", "1000", "1000000"})
    int n;

    @Param({"STANDARD", "LAZY"})
    Algorithm algorithm;

    private ProactiveEngine engine;

    @Setup(Level.Trial)
    public void setUp() {
        Workload.quietLogs();
        engine = ProactiveEngine.builder().algorithm(algorithm).build();
        engine.startFresh(CountingRule.many(n));
    }

    /** One engine iteration: n rules run and regenerated. */
    @Benchmark
    public int iteration(RuleCounter counter) {
        int run = engine.runIteration().rulesRun();
        counter.rules += run;
        return run;
    }
}
