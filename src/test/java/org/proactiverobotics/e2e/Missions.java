package org.proactiverobotics.e2e;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/** Runs missions for the end-to-end tests, each on a fresh database, and remembers H2 runs. */
final class Missions {

    /** A finished mission: its report and the files it wrote. */
    record Run(MissionReport report, Path outDir) {
        List<JsonObject> trace() throws IOException {
            return Files.readAllLines(outDir.resolve("trace.jsonl")).stream()
                    .map(line -> JsonParser.parseString(line).getAsJsonObject()).toList();
        }

        /** The report without what depends on the machine's speed or the database kind. */
        MissionReport deterministicPart() {
            MissionReport r = report;
            return new MissionReport(r.world(), r.success(), r.outcome(), r.strategy(), "-", r.checkpointsReached(),
                    r.checkpointsTotal(), r.simTimeS(), 0, 0, r.controlSteps(), r.engineIterations(), r.distanceM(),
                    r.collisions(), r.minClearanceM(), r.minBattery(), r.finalBattery(), r.recharges(), r.commandWins(),
                    r.ruleFailures(), r.poseError(), null);
        }
    }

    private static final Map<String, Run> H2_RUNS = new ConcurrentHashMap<>();

    private Missions() {
    }

    /**
     * @param name       the world's name
     * @param timeLimitS its maxSimTimeS, seconds
     * @return the bundled reference arena with that name and time limit (seed 7): a mission that ends quickly
     */
    static WorldSpec shortReferenceArena(String name, double timeLimitS) {
        WorldSpec ref = WorldFiles.bundled("reference-arena");
        return new WorldSpec(name, ref.timeStepMs(), timeLimitS, 7, ref.arena(), ref.robot(), ref.obstacles(),
                ref.checkpoints(), ref.checkpointRadiusM(), ref.rechargeStation(), ref.battery());
    }

    /** The run of a bundled world with safety-first on H2, done once per test JVM. */
    static Run onH2(String world) {
        return H2_RUNS.computeIfAbsent(world, w -> run(w, DatabaseKind.H2, "safety-first", sim -> { }));
    }

    static Run run(String world, DatabaseKind kind, String strategy, Consumer<Simulation> onStep) {
        try (TestDatabase db = TestDatabases.open(kind)) {
            return run(world, db, strategy, onStep);
        } catch (java.sql.SQLException e) {
            throw new IllegalStateException(e);
        }
    }

    static Run run(String world, TestDatabase db, String strategy, Consumer<Simulation> onStep) {
        return run(world, db, strategy, onStep, UnaryOperator.identity());
    }

    /** The run of a bundled world on a database, with sensor noise. */
    static Run run(String world, TestDatabase db, String strategy, org.proactiverobotics.app.mission.NoiseLevel noise) {
        MissionOptions options = new MissionOptions(WorldFiles.bundled(world), db.jdbcUrl(), db.user(), db.password(),
                strategy, 1).withNoise(noise);
        return run(options, sim -> { }, UnaryOperator.identity());
    }

    /** A run whose engine reads and writes through {@code tables} (a fault injected, a recorder). */
    static Run run(String world, TestDatabase db, String strategy, Consumer<Simulation> onStep,
                   UnaryOperator<EngineTables> tables) {
        MissionOptions options = new MissionOptions(WorldFiles.bundled(world), db.jdbcUrl(), db.user(), db.password(),
                strategy, 1);
        return run(options, onStep, tables);
    }

    /** The run of a bundled world over the in-process direct link: no database. */
    static Run direct(String world, String strategy) {
        MissionOptions options = new MissionOptions(WorldFiles.bundled(world), null, null, null, strategy, 1)
                .withLink(MissionOptions.Link.DIRECT);
        return run(options, sim -> { }, UnaryOperator.identity());
    }

    /** The run of any world over the in-process direct link. */
    static Run direct(WorldSpec world, String strategy) {
        MissionOptions options = new MissionOptions(world, null, null, null, strategy, 1).withLink(MissionOptions.Link.DIRECT);
        return run(options, sim -> { }, UnaryOperator.identity());
    }

    /** The run of any world over the in-process direct link, with sensor noise. */
    static Run direct(WorldSpec world, String strategy, org.proactiverobotics.app.mission.NoiseLevel noise) {
        MissionOptions options = new MissionOptions(world, null, null, null, strategy, 1).withLink(MissionOptions.Link.DIRECT)
                .withNoise(noise);
        return run(options, sim -> { }, UnaryOperator.identity());
    }

    /** The run of any world on a new database of a kind, with sensor noise. */
    static Run run(WorldSpec world, DatabaseKind kind, org.proactiverobotics.app.mission.NoiseLevel noise) {
        try (TestDatabase db = TestDatabases.open(kind)) {
            MissionOptions options = new MissionOptions(world, db.jdbcUrl(), db.user(), db.password(), "safety-first", 1)
                    .withNoise(noise);
            return run(options, sim -> { }, UnaryOperator.identity());
        } catch (java.sql.SQLException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The run of any world on a database. */
    static Run run(WorldSpec world, TestDatabase db, String strategy) {
        MissionOptions options = new MissionOptions(world, db.jdbcUrl(), db.user(), db.password(), strategy, 1);
        return run(options, sim -> { }, UnaryOperator.identity());
    }

    private static Run run(MissionOptions options, Consumer<Simulation> onStep, UnaryOperator<EngineTables> tables) {
        String world = options.world().name();
        try {
            Path out = Files.createTempDirectory("mission-" + world + "-");
            MissionReport report = new Mission(options).onStep(onStep).engineTables(tables).run(out);
            return new Run(report, out);
        } catch (IOException | java.sql.SQLException e) {
            throw new IllegalStateException("mission " + world + " over " + options.link() + " could not run", e);
        }
    }
}
