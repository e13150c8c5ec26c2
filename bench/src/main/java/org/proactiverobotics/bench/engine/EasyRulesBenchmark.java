package org.proactiverobotics.bench.engine;

import java.util.concurrent.TimeUnit;
import org.jeasy.rules.api.Facts;
import org.jeasy.rules.api.Rules;
import org.jeasy.rules.api.RulesEngine;
import org.jeasy.rules.core.BasicRule;
import org.jeasy.rules.core.DefaultRulesEngine;
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

/**
 * The same workload in Easy Rules 4.1: n rules, each with its own counter; one {@code fire} runs
 * every rule once, as one engine iteration does (Easy Rules keeps its rules, so no cloning).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Fork(value = 1, jvmArgsAppend = "-Xmx4g")
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 3, time = 1)
public class EasyRulesBenchmark {

    @Param({"10", "1000", "1000000"})
    int n;

    private Rules rules;
    private RulesEngine engine;
    private Facts facts;

    /** The workload as an Easy Rules rule; names are unique because Easy Rules keeps rules in a sorted set. */
    static final class EasyCountingRule extends BasicRule {
        long value;

        EasyCountingRule(String name) {
            super(name);
        }

        @Override
        public boolean evaluate(Facts facts) {
            return Workload.condition(value);
        }

        @Override
        public void execute(Facts facts) {
            value = Workload.action(value);
        }
    }

    @Setup(Level.Trial)
    public void setUp() {
        Workload.quietLogs();
        rules = new Rules();
        for (int i = 0; i < n; i++) {
            rules.register(new EasyCountingRule(String.format("r%08d", i)));
        }
        engine = new DefaultRulesEngine();
        facts = new Facts();
    }

    /** One fire: n rules evaluated and executed. */
    @Benchmark
    public void fire(RuleCounter counter) {
        engine.fire(rules, facts);
        counter.rules += n;
    }
}
