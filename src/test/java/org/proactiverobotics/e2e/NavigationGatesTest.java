package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
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
import org.proactiverobotics.app.generate.Solvability;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Issue 17's gates, on generated worlds over the direct link: every kind with the default robot,
 * and pillars, rooms and clutter with 0.2 m and 0.3 m robots, each world without noise and with
 * {@code --noise small}: every mission accomplished, no collision, the battery never flat; on pillar
 * fields, rooms and mazes with the default robot the mean simulated time of the noiseless missions
 * within twice the planner's path at top speed. 780 missions, about 65 s on two cores: in the normal
 * suite, and alone with {@code -Pgates}; the worlds per case and the seed are the properties {@code proactive.gates.worlds} (default 30) and
 * {@code proactive.gates.seed} (default 17). A failing mission's folder is kept and named.
 */
@Tag("gates")
class NavigationGatesTest {

    private static final int WORLDS = Integer.getInteger("proactive.gates.worlds", 30);
    private static final long SEED = Long.getLong("proactive.gates.seed", 17);

    static Stream<Arguments> cases() {
        List<Arguments> cases = new ArrayList<>();
        for (WorldGenerator.Kind kind : WorldGenerator.Kind.values()) {
            cases.add(Arguments.of(kind, WorldSpec.Robot.DEFAULT_RADIUS_M));
        }
        for (double radiusM : new double[] {0.2, 0.3}) {
            for (WorldGenerator.Kind kind : List.of(WorldGenerator.Kind.PILLARS, WorldGenerator.Kind.ROOMS, WorldGenerator.Kind.CLUTTERED)) {
                cases.add(Arguments.of(kind, radiusM));
            }
        }
        return cases.stream();
    }

    /** One mission's result, or why it failed the gate. */
    private record Result(WorldSpec world, NoiseLevel noise, MissionReport report, double plannedM, String failure) {
    }

    @ParameterizedTest(name = "{0}, robot radius {1} m")
    @MethodSource("cases")
    void everyGeneratedWorldIsAccomplishedWithoutCollisionOrAFlatBattery(WorldGenerator.Kind kind, double radiusM) throws Exception {
        WorldGenerator generator = new WorldGenerator(kind, radiusM);
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Runtime.getRuntime().availableProcessors()));
        List<Future<Result>> futures = new ArrayList<>();
        try {
            for (int n = 1; n <= WORLDS; n++) {
                WorldSpec world = generator.world(SEED, n);
                double plannedM = Solvability.of(world).lengthM();
                for (NoiseLevel noise : List.of(NoiseLevel.NONE, NoiseLevel.SMALL)) {
                    futures.add(pool.submit(() -> run(world, noise, plannedM)));
                }
            }
            List<Result> results = new ArrayList<>();
            for (Future<Result> f : futures) {
                results.add(f.get());
            }
            List<String> failures = results.stream().filter(r -> r.failure() != null).map(Result::failure).toList();
            double noiselessTime = results.stream().filter(r -> r.noise() == NoiseLevel.NONE && r.failure() == null)
                    .mapToDouble(r -> r.report().simTimeS() / (r.plannedM() / r.world().robot().maxSpeedMps())).average().orElse(0);
            System.out.printf(Locale.ROOT, "gates: %s, radius %.2f m: %d of %d missions passed; mean time over the planner's path %.2f (no noise)%n",
                    kind.label(), radiusM, results.size() - failures.size(), results.size(), noiselessTime);
            assertThat(failures).as("%s worlds, seed %d", kind.label(), SEED).isEmpty();
            if (radiusM == WorldSpec.Robot.DEFAULT_RADIUS_M
                    && List.of(WorldGenerator.Kind.PILLARS, WorldGenerator.Kind.ROOMS, WorldGenerator.Kind.MAZE).contains(kind)) {
                assertThat(noiselessTime).as("mean simulated time over the planner's path at top speed").isLessThanOrEqualTo(2.0);
            }
        } finally {
            pool.shutdownNow();
        }
    }

    private static Result run(WorldSpec world, NoiseLevel noise, double plannedM) {
        Missions.Run run = Missions.direct(world, "safety-first", noise);
        MissionReport r = run.report();
        String failure = r.outcome() != Outcome.MISSION_ACCOMPLISHED || r.collisions() > 0 || r.minBattery() <= 0
                ? String.format(Locale.ROOT, "%s, %s noise: %s, %d collisions, battery min %.1f %% (see %s)",
                        world.name(), noise.label(), r.outcome(), r.collisions(), r.minBattery(), run.outDir())
                : null;
        if (failure == null) {
            delete(run.outDir()); // about 2 MB a mission: keep only what a failure needs looked at
        }
        return new Result(world, noise, r, plannedM, failure);
    }

    static void delete(Path dir) {
        try (Stream<Path> paths = Files.walk(dir)) {
            for (Path p : paths.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
