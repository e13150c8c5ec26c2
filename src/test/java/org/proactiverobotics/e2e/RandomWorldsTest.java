package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * "Any reasonable world": arenas cluttered at random (seeded) with convex obstacles, gaps of at
 * least 0.65 m between them, and the start, the checkpoints and the station kept 0.9 m clear.
 * Every one must be accomplished in order, without a single collision.
 */
class RandomWorldsTest {

    /** Six worlds by default; {@code -Dproactive.randomWorlds=N} tries more. */
    static LongStream seeds() {
        return LongStream.rangeClosed(1, Long.getLong("proactive.randomWorlds", 6));
    }

    @ParameterizedTest(name = "random world {0}")
    @MethodSource("seeds")
    void aRandomClutteredWorldIsAccomplishedWithoutCollision(long seed) throws Exception {
        WorldSpec world = WorldFiles.parse(randomWorld(seed), "random-" + seed);
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Path out = Files.createTempDirectory("random-world-");
            MissionReport report = new Mission(new MissionOptions(world, db.jdbcUrl(), db.user(), db.password(),
                    "safety-first", 1)).run(out);
            assertThat(report.outcome()).as("random world %d (see %s)", seed, out).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
            assertThat(report.collisions()).as("collisions in random world %d (see %s)", seed, out).isZero();
            assertThat(report.minBattery()).isPositive();
        }
    }

    /** A reasonable world drawn from a seed, as world-file JSON. */
    static String randomWorld(long seed) {
        return clutteredWorld("random-" + seed, seed, 16, 0.65, 0);
    }

    /**
     * A cluttered world drawn from a seed, as world-file JSON: three checkpoints, up to
     * {@code obstacles} boxes and circles at least {@code gapM} apart, the default arena and station.
     *
     * @param maxSpeedMps the robot's top speed, m/s (0: the world file's default)
     */
    static String clutteredWorld(String name, long seed, int maxObstacles, double gapM, double maxSpeedMps) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] start = {0.0, -4.0};
        List<double[]> keepClear = new ArrayList<>();
        keepClear.add(start);
        double[] station = {-3.0, -2.5};
        keepClear.add(station);
        JsonArray checkpoints = new JsonArray();
        while (checkpoints.size() < 3) {
            double x = random.nextDouble(-3.3, 3.3);
            double y = random.nextDouble(-3.3, 3.3);
            if (Math.hypot(x, y) < 3.5 && keepClear.stream().allMatch(p -> Math.hypot(p[0] - x, p[1] - y) > 1.5)) {
                keepClear.add(new double[] {x, y});
                JsonObject cp = new JsonObject();
                cp.addProperty("x", round(x));
                cp.addProperty("y", round(y));
                checkpoints.add(cp);
            }
        }
        List<double[]> placed = new ArrayList<>(); // x, y, bounding radius
        JsonArray obstacles = new JsonArray();
        for (int attempt = 0; attempt < 2000 && placed.size() < maxObstacles; attempt++) {
            double x = random.nextDouble(-3.9, 3.9);
            double y = random.nextDouble(-3.9, 3.9);
            double r = random.nextDouble(0.15, 0.5);
            boolean fits = Math.hypot(x, y) + r < 4.3
                    && keepClear.stream().allMatch(p -> Math.hypot(p[0] - x, p[1] - y) > r + 0.9)
                    && placed.stream().allMatch(o -> Math.hypot(o[0] - x, o[1] - y) > r + o[2] + gapM);
            if (!fits) {
                continue;
            }
            placed.add(new double[] {x, y, r});
            JsonObject o = new JsonObject();
            o.addProperty("x", round(x));
            o.addProperty("y", round(y));
            if (placed.size() % 2 == 0) {
                o.addProperty("shape", "circle");
                o.addProperty("radiusM", round(r * 0.95));
            } else { // a box whose half-diagonal stays within r
                o.addProperty("shape", "box");
                o.addProperty("widthM", round(r * 1.4));
                o.addProperty("heightM", round(r * 1.0));
                o.addProperty("angleDeg", 15.0 * random.nextInt(12));
            }
            obstacles.add(o);
        }
        JsonObject world = new JsonObject();
        world.addProperty("name", name);
        world.addProperty("seed", seed);
        world.addProperty("maxSimTimeS", 300);
        JsonObject arena = new JsonObject();
        arena.addProperty("radiusM", 5.0);
        world.add("arena", arena);
        JsonObject robot = new JsonObject();
        robot.addProperty("x", start[0]);
        robot.addProperty("y", start[1]);
        robot.addProperty("headingDeg", 90.0);
        if (maxSpeedMps > 0) {
            robot.addProperty("maxSpeedMps", maxSpeedMps);
        }
        world.add("robot", robot);
        world.add("obstacles", obstacles);
        world.add("checkpoints", checkpoints);
        JsonObject st = new JsonObject();
        st.addProperty("x", station[0]);
        st.addProperty("y", station[1]);
        st.addProperty("radiusM", 0.35);
        world.add("rechargeStation", st);
        return world.toString();
    }

    private static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }
}
