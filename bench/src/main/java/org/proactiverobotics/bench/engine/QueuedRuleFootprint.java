package org.proactiverobotics.bench.engine;

import java.lang.management.ManagementFactory;
import java.lang.ref.Reference;
import java.util.function.IntFunction;
import org.jeasy.rules.api.Facts;
import org.jeasy.rules.api.Rules;
import org.jeasy.rules.core.DefaultRulesEngine;
import org.proactiverobotics.engine.ProactiveEngine;

/**
 * The heap each queued rule costs, measured rather than computed: heap in use (after full GCs)
 * with n rules queued, minus before, over n. For the engine it is the rule object plus its
 * slots in currentQueue and nextQueue after one iteration (both deques keep their capacity).
 *
 * <pre>java -XX:+UseSerialGC -Xmx4g -cp bench/target/benchmarks.jar org.proactiverobotics.bench.engine.QueuedRuleFootprint [n]</pre>
 */
public final class QueuedRuleFootprint {

    private QueuedRuleFootprint() {
    }

    public static void main(String[] args) throws Exception {
        Workload.quietLogs();
        int n = args.length > 0 ? Integer.parseInt(args[0]) : 1_000_000;
        report("ProactiveEngine (CountingRule, after 1 iteration)", n, size -> {
            ProactiveEngine engine = ProactiveEngine.builder().build();
            engine.startFresh(CountingRule.many(size));
            engine.runIteration();
            return engine;
        });
        report("Easy Rules 4.1 (BasicRule in Rules, after 1 fire)", n, size -> {
            Rules rules = new Rules();
            for (int i = 0; i < size; i++) {
                rules.register(new EasyRulesBenchmark.EasyCountingRule(String.format("r%08d", i)));
            }
            Workload.quietLogs();
            new DefaultRulesEngine().fire(rules, new Facts());
            return rules;
        });
        report("plain loop (Cell[] of one long)", n, size -> {
            PlainLoopBenchmark.Cell[] cells = new PlainLoopBenchmark.Cell[size];
            for (int i = 0; i < size; i++) {
                cells[i] = new PlainLoopBenchmark.Cell();
            }
            return cells;
        });
    }

    private static void report(String what, int n, IntFunction<Object> build) throws InterruptedException {
        long before = usedAfterGc();
        Object kept = build.apply(n);
        long after = usedAfterGc();
        System.out.printf("%-52s n=%,d  %.1f bytes per queued rule%n", what, n, (after - before) / (double) n);
        Reference.reachabilityFence(kept); // 'kept' must live through the measurement
    }

    private static long usedAfterGc() throws InterruptedException {
        for (int i = 0; i < 4; i++) {
            System.gc();
            Thread.sleep(50);
        }
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }
}
