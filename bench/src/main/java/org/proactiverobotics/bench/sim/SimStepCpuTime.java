package org.proactiverobotics.bench.sim;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;

/**
 * {@link SimStepBenchmark}'s three methods timed by the thread's processor time instead of wall time, for a
 * machine shared with other jobs (where JMH's throughput swings by a factor of two or more): for each world,
 * 3 warm-up and 5 measured iterations of N steps, each from a restart, and the median in microseconds a step.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.sim.SimStepCpuTime 300000 reference 1000 floor56x60 floor100x100
 * </pre>
 */
public final class SimStepCpuTime {

    private SimStepCpuTime() {
    }

    /** @param args steps per iteration, then the worlds ({@link SimStepBenchmark#world}'s values) */
    public static void main(String[] args) {
        int n = Integer.parseInt(args[0]);
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        double sink = 0;
        for (int k = 1; k < args.length; k++) {
            for (int m = 0; m < 3; m++) {
                SimStepBenchmark b = new SimStepBenchmark();
                b.world = args[k];
                b.noise = false;
                b.buildWorld();
                double[] us = new double[5];
                for (int it = 0; it < 8; it++) {
                    b.restart();
                    long t0 = mx.getCurrentThreadCpuTime();
                    for (int i = 0; i < n; i++) {
                        sink += m == 0 ? b.stepAndReadAllSensors() : m == 1 ? b.stepOnly() : b.stepOnWanderPath();
                    }
                    long t = mx.getCurrentThreadCpuTime() - t0;
                    if (it >= 3) {
                        us[it - 3] = t / 1e3 / n;
                    }
                }
                Arrays.sort(us);
                System.out.printf(Locale.ROOT, "%-14s %-22s median %.3f us/step (min %.3f, max %.3f)%n", args[k],
                        m == 0 ? "stepAndReadAllSensors" : m == 1 ? "stepOnly" : "stepOnWanderPath", us[2], us[0], us[4]);
            }
        }
        // Keeps the JIT compiler from dropping the steps' results.
        if (sink == 42.0) {
            System.out.println();
        }
    }
}
