package org.proactiverobotics.bench.mission;

import java.util.Locale;
import java.util.Map;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.bench.engine.Workload;
import org.proactiverobotics.engine.Algorithm;
import org.proactiverobotics.engine.IterationListener;
import org.proactiverobotics.engine.IterationSummary;
import org.proactiverobotics.engine.RuleTrace;
import org.proactiverobotics.engine.scenario.localisation.LocalisationScenario;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * What the Localisation scenario costs per engine iteration, measured in whole missions: the
 * time from the rule before it to its own end, taken by an iteration listener (the rule's reads,
 * its filter, its scan match, its write), against the whole iteration's time. Over the direct
 * link, so that no database round trip is counted; each mission run {@code --repeat} times, the
 * first of them a warm-up that is not counted.
 *
 * <p>A plain harness, not JMH: the cost asked for is the rule's in a running mission, with the
 * map, scans and readings a mission gives it, and JMH would need all of that built by hand.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.proactiverobotics.bench.mission.LocaliserCost \
 *     --world reference-arena --noise indoor --repeat 6
 * </pre>
 * {@code --world} takes a bundled world's name or a world file ({@code .json}).
 */
public final class LocaliserCost implements IterationListener {

    private long ruleStartNs;
    private long iterationStartNs;
    long localisationNs;
    long iterationNs;
    long iterations;

    private LocaliserCost() {
    }

    @Override
    public void iterationStarted(long iteration, int queued) {
        iterationStartNs = System.nanoTime();
        ruleStartNs = iterationStartNs;
    }

    @Override
    public void ruleRan(RuleTrace trace) {
        long now = System.nanoTime();
        if (LocalisationScenario.NAME.equals(trace.rule().scenario())) {
            localisationNs += now - ruleStartNs;
        }
        ruleStartNs = now;
    }

    @Override
    public void iterationEnded(IterationSummary summary) {
        iterationNs += System.nanoTime() - iterationStartNs;
        iterations++;
    }

    public static void main(String[] args) throws Exception {
        Workload.quietLogs();
        Map<String, String> opt = LongRun.Args.parse(args);
        String name = opt.getOrDefault("world", "reference-arena");
        NoiseLevel noise = NoiseLevel.of(opt.getOrDefault("noise", "indoor"));
        int repeat = Integer.parseInt(opt.getOrDefault("repeat", "6"));
        WorldSpec world = name.endsWith(".json") ? WorldFiles.load(java.nio.file.Path.of(name)) : WorldFiles.bundled(name);
        LocaliserCost total = new LocaliserCost();
        for (int r = 0; r < repeat; r++) {
            LocaliserCost cost = new LocaliserCost();
            String outcome;
            try (Rig rig = Rig.direct(world, 1, Algorithm.LAZY, noise.sensorNoise(), cost)) {
                GroundTruth truth = rig.truth();
                while (true) {
                    rig.step();
                    if (truth.checkpointsReached() == truth.checkpointsTotal()) {
                        outcome = "accomplished";
                        break;
                    }
                    if (truth.batteryPct() <= 0.0 || rig.sim.timeLimitReached()) {
                        outcome = "not accomplished";
                        break;
                    }
                }
            }
            System.out.printf(Locale.ROOT, "run %d%s: %s, %d iterations, Localisation %.1f µs / iteration of %.1f µs%n", r + 1,
                    r == 0 ? " (warm-up)" : "", outcome, cost.iterations, cost.localisationNs / 1e3 / cost.iterations,
                    cost.iterationNs / 1e3 / cost.iterations);
            if (r > 0) {
                total.localisationNs += cost.localisationNs;
                total.iterationNs += cost.iterationNs;
                total.iterations += cost.iterations;
            }
        }
        System.out.printf(Locale.ROOT, "LocaliserCost world=%s noise=%s: Localisation %.1f µs per iteration (%.1f %% of the"
                        + " engine's %.1f µs), over %d iterations%n", name, noise.label(),
                total.localisationNs / 1e3 / total.iterations, 100.0 * total.localisationNs / total.iterationNs,
                total.iterationNs / 1e3 / total.iterations, total.iterations);
    }
}
