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

/** The floor: a plain loop over n objects calling the same condition and action, no engine at all. */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Fork(value = 1, jvmArgsAppend = "-Xmx4g")
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 3, time = 1)
public class PlainLoopBenchmark {

    @Param({"10", "1000", "1000000"})
    int n;

    /** One rule's state, as a rule object holds it. */
    static final class Cell {
        long value;
    }

    private Cell[] cells;

    @Setup(Level.Trial)
    public void setUp() {
        cells = new Cell[n];
        for (int i = 0; i < n; i++) {
            cells[i] = new Cell();
        }
    }

    /** One pass: n conditions and actions. */
    @Benchmark
    public void pass(RuleCounter counter) {
        for (Cell cell : cells) {
            if (Workload.condition(cell.value)) {
                cell.value = Workload.action(cell.value);
            }
        }
        counter.rules += cells.length;
    }
}
