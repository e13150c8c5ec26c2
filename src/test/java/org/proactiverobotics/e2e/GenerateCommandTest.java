package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.proactiverobotics.app.generate.GridPlanner;
import org.proactiverobotics.app.generate.Solvability;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * {@code generate} (issue 13): N valid, solvable world files of a kind, the same for the same seed;
 * the planner finds no way through a wall and sees a battery too small for the tour.
 */
class GenerateCommandTest extends CommandLineTest {

    @TempDir
    Path tmp;

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"cluttered", "traps", "corridors", "battery", "pillars", "rooms", "maze"})
    void writesValidSolvableWorldsOfTheKindTheSameForTheSameSeed(String kind) throws Exception {
        Path a = tmp.resolve("a");
        Path b = tmp.resolve("b");
        assertThat(run("generate", "--kind", kind, "--count", "3", "--seed", "5", "--out", a.toString())).as(err.toString())
                .isZero();
        // a kind's name in capitals is the same kind
        assertThat(run("generate", "--kind", kind.toUpperCase(Locale.ROOT), "--count", "3", "--seed", "5", "--out", b.toString()))
                .as(err.toString()).isZero();
        List<Path> files;
        try (Stream<Path> s = Files.list(a)) {
            files = s.sorted().toList();
        }
        assertThat(files).extracting(p -> p.getFileName().toString())
                .containsExactly(kind + "-001.json", kind + "-002.json", kind + "-003.json");
        for (Path file : files) {
            WorldSpec world = WorldFiles.load(file); // valid, or this throws naming its problems
            Solvability plan = Solvability.of(world);
            assertThat(plan.solvable()).as(file + ": " + plan.reason()).isTrue();
            // the tour at a third of top speed (a fifth for corridors, explored wrong way first), and a margin
            int slowdown = kind.equals("corridors") ? 5 : 3;
            assertThat(plan.lengthM() / (world.robot().maxSpeedMps() / slowdown)).isLessThan(world.maxSimTimeS());
            if (kind.equals("battery")) {
                assertThat(plan.recharges()).as("a battery world needs a recharge").isPositive();
            }
            assertThat(Files.readString(file)).isEqualTo(Files.readString(b.resolve(file.getFileName())));
            assertThat(run("validate", "--world", file.toString())).isZero();
        }
        assertThat(Files.readString(a.resolve(kind + "-001.json"))).isNotEqualTo(Files.readString(a.resolve(kind + "-002.json")));
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"pillars", "rooms", "maze", "corridors"})
    void aLargerRobotGetsWiderPassagesEachCheckedOnItsOwnFootprint(String kind) throws Exception {
        Path out = tmp.resolve("r");
        assertThat(run("generate", "--kind", kind, "--count", "2", "--seed", "3", "--robot-radius", "0.3", "--out",
                out.toString())).as(err.toString()).isZero();
        for (String name : List.of(kind + "-001.json", kind + "-002.json")) {
            WorldSpec world = WorldFiles.load(out.resolve(name));
            assertThat(world.robot().radiusM()).isEqualTo(0.3);
            Solvability plan = Solvability.of(world); // on the 0.3 m robot's footprint plus the clearance
            assertThat(plan.solvable()).as(name + ": " + plan.reason()).isTrue();
        }
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"pillars", "rooms", "maze", "cluttered", "traps", "battery"})
    void theSmallestRobotGetsWorldsItsPlannerCanPass(String kind) throws Exception {
        double radius = "rooms".equals(kind) ? 0.07 : 0.05; // each kind's smallest (rooms: a 5 cm robot's doors are closed by the clearance)
        Path out = tmp.resolve("small");
        assertThat(run("generate", "--kind", kind, "--count", "2", "--seed", "3", "--robot-radius", String.valueOf(radius),
                "--out", out.toString())).as(err.toString()).isZero();
        for (String name : List.of(kind + "-001.json", kind + "-002.json")) {
            WorldSpec world = WorldFiles.load(out.resolve(name));
            assertThat(world.robot().radiusM()).isEqualTo(radius);
            assertThat(Solvability.of(world).solvable()).isTrue();
        }
    }

    @Test
    void aRobotTooSmallForTheKindIsBadInputNamedUpFrontNotAStackTrace() {
        Path out = tmp.resolve("tiny");
        assertThat(run("generate", "--kind", "corridors", "--count", "1", "--robot-radius", "0.05", "--out", out.toString()))
                .isEqualTo(2);
        assertThat(err.toString()).contains("--robot-radius 0.05 is too small for corridors worlds: from 0.1 m")
                .doesNotContain("Exception");
        assertThat(run("generate", "--kind", "rooms", "--count", "1", "--robot-radius", "0.06", "--out", out.toString()))
                .isEqualTo(2);
        assertThat(err.toString()).contains("too small for rooms worlds: from 0.07 m");
        assertThat(out).doesNotExist();
    }

    @Test
    void thePlannerFindsNoWayThroughAClosedWallAndABatteryTooSmall() {
        WorldSpec ref = WorldFiles.bundled("reference-arena");
        assertThat(Solvability.of(ref).solvable()).isTrue();
        // a wall right across the arena between the start (south) and every checkpoint
        WorldSpec walled = ref.withObstacles(List.of(WorldSpec.Obstacle.box(0, ref.robot().y() + 0.6,
                3 * ref.arena().radiusM(), 0.2, 0)));
        GridPlanner planner = new GridPlanner(walled, Solvability.CLEARANCE_M);
        WorldSpec.Checkpoint first = ref.checkpoints().get(0);
        assertThat(planner.distance(ref.robot().x(), ref.robot().y(), first.x(), first.y())).isInfinite();
        assertThat(Solvability.of(walled).reason()).contains("checkpoints[0] cannot be reached");
        WorldSpec flat = ref.withBattery(new WorldSpec.Battery(1.0, 5.0, 2.0, 10.0));
        assertThat(Solvability.of(flat).solvable()).isFalse();
    }

    @Test
    void badInputExitsTwoAndWritesNothing() throws Exception {
        Path out = tmp.resolve("out");
        assertThat(run("generate", "--kind", "mazes", "--count", "2", "--out", out.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--kind must be one of cluttered, traps, corridors, battery");
        assertThat(run("generate", "--kind", "traps", "--count", "0", "--out", out.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--count");
        assertThat(run("generate", "--kind", "rooms", "--count", "1", "--robot-radius", "0.5", "--out", out.toString()))
                .isEqualTo(2);
        assertThat(err.toString()).contains("--robot-radius must be from 0.05 to 0.3");
        assertThat(out).doesNotExist();
        Files.createDirectories(out);
        Files.writeString(out.resolve("mine.json"), "{}");
        assertThat(run("generate", "--kind", "traps", "--count", "1", "--out", out.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("exists and is not empty");
        try (Stream<Path> s = Files.list(out)) {
            assertThat(s.count()).isEqualTo(1);
        }
    }
}
