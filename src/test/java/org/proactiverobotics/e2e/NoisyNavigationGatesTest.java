package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Issue 32's gates, on generated worlds over the direct link with the default robot: under
 * {@code --noise realistic} at least 95 % of the missions of every kind accomplished, under
 * {@code --noise indoor} (no GPS) at least 90 % on rooms, maze, corridors, cluttered and pillars;
 * at every level no collision and the battery never flat; and the mean pose error over a kind's
 * missions within 5 cm (realistic) and 10 cm (indoor). 240 missions, about two minutes on two
 * cores: in the normal suite, and with {@code -Pgates}. Twenty worlds a case, so that one failure
 * in twenty is 95 %. The worlds per case and the seed are the
 * properties {@code proactive.gates.noisyWorlds} (default 20) and {@code proactive.gates.seed}
 * (default 17). A failing mission's folder is kept and named.
 */
@Tag("gates")
class NoisyNavigationGatesTest {

    private static final int WORLDS = Integer.getInteger("proactive.gates.noisyWorlds", 20);
    private static final long SEED = Long.getLong("proactive.gates.seed", 17);

    static Stream<Arguments> cases() {
        List<Arguments> cases = new ArrayList<>();
        for (WorldGenerator.Kind kind : WorldGenerator.Kind.values()) {
            cases.add(Arguments.of(NoiseLevel.REALISTIC, kind, 0.95, 0.05));
        }
        for (WorldGenerator.Kind kind : List.of(WorldGenerator.Kind.ROOMS, WorldGenerator.Kind.MAZE, WorldGenerator.Kind.CORRIDORS,
                WorldGenerator.Kind.CLUTTERED, WorldGenerator.Kind.PILLARS)) {
            cases.add(Arguments.of(NoiseLevel.INDOOR, kind, 0.90, 0.10));
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0}, {1}")
    @MethodSource("cases")
    void enoughMissionsAreAccomplishedSafelyAndTheEstimateStaysClose(NoiseLevel noise, WorldGenerator.Kind kind,
                                                                      double successRate, double meanPoseErrorM) throws Exception {
        WorldGenerator generator = new WorldGenerator(kind, WorldSpec.Robot.DEFAULT_RADIUS_M);
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Runtime.getRuntime().availableProcessors()));
        List<Future<Missions.Run>> futures = new ArrayList<>();
        try {
            for (int n = 1; n <= WORLDS; n++) {
                WorldSpec world = generator.world(SEED, n);
                futures.add(pool.submit(() -> Missions.direct(world, "safety-first", noise)));
            }
            List<String> unsafe = new ArrayList<>();
            List<String> failed = new ArrayList<>();
            double poseErrorSumM = 0;
            for (Future<Missions.Run> f : futures) {
                Missions.Run run = f.get();
                MissionReport r = run.report();
                String what = String.format(Locale.ROOT, "%s: %s, %d collisions, battery min %.1f %% (see %s)",
                        r.world(), r.outcome(), r.collisions(), r.minBattery(), run.outDir());
                if (r.collisions() > 0 || r.minBattery() <= 0) {
                    unsafe.add(what);
                }
                if (r.outcome() != Outcome.MISSION_ACCOMPLISHED) {
                    failed.add(what);
                } else if (r.collisions() == 0 && r.minBattery() > 0) {
                    NavigationGatesTest.delete(run.outDir()); // about 2 MB a mission: keep what a failure needs looked at
                }
                poseErrorSumM += r.poseError().meanM();
            }
            double rate = 1.0 - (double) failed.size() / WORLDS;
            double poseErrorM = poseErrorSumM / WORLDS;
            System.out.printf(Locale.ROOT, "gates: %s noise, %s: %d of %d accomplished, mean pose error %.3f m%n",
                    noise.label(), kind.label(), WORLDS - failed.size(), WORLDS, poseErrorM);
            assertThat(unsafe).as("%s noise, %s worlds, seed %d: collisions or a flat battery", noise.label(), kind.label(), SEED)
                    .isEmpty();
            assertThat(rate).as("%s noise, %s worlds, seed %d: accomplished; failed: %s", noise.label(), kind.label(), SEED, failed)
                    .isGreaterThanOrEqualTo(successRate);
            assertThat(poseErrorM).as("mean pose error, metres").isLessThanOrEqualTo(meanPoseErrorM);
        } finally {
            pool.shutdownNow();
        }
    }
}
