package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.app.mission.RobotReport;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * A world with several robots through {@code run}'s mission: one world, an engine and a controller per robot; the
 * same run on the direct link, H2 and MariaDB, and with one or two engine threads.
 */
class FleetMissionTest {

    /** The time limit of the runs compared, simulated seconds. */
    private static final double SHORT_S = 6.0;

    /** Two robots whose missions cross near the arena's centre, a third that goes round alone (all done by 17 s). */
    static WorldSpec crossing() {
        return crossing(40.0);
    }

    /**
     * @param timeLimitS the world's maxSimTimeS: 6 s keeps the database runs short (each robot still drives,
     *                   senses the others and decides every step)
     */
    static WorldSpec crossing(double timeLimitS) {
        List<WorldSpec.RobotEntry> robots = List.of(
                new WorldSpec.RobotEntry(1, new WorldSpec.Robot(-2.5, -1.0, 0.0, 0.12, 0.5, 1.0),
                        List.of(new WorldSpec.Checkpoint(2.5, -0.5))),
                new WorldSpec.RobotEntry(2, new WorldSpec.Robot(2.5, -1.5, 180.0, 0.12, 0.5, 1.0),
                        List.of(new WorldSpec.Checkpoint(-2.5, -0.5))),
                new WorldSpec.RobotEntry(5, new WorldSpec.Robot(0.0, 3.0, 0.0, 0.10, 0.4, 1.0),
                        List.of(new WorldSpec.Checkpoint(2.0, 2.0), new WorldSpec.Checkpoint(-2.0, 2.5))));
        return WorldSpec.fleet("crossing", 32, timeLimitS, 11, new WorldSpec.Arena(4.0), robots,
                List.of(WorldSpec.Obstacle.box(0.0, 1.0, 0.6, 0.6, 0.0)), 0.25,
                List.of(new WorldSpec.RechargeStation(-3.0, 2.0, 0.35)), WorldSpec.Battery.DEFAULT);
    }

    private static Missions.Run run(MissionOptions options, int threads) throws Exception {
        Path out = Files.createTempDirectory("fleet-mission-");
        MissionReport report = new Mission(options).threads(threads).engineTables(UnaryOperator.identity()).run(out);
        return new Missions.Run(report, out);
    }

    private static MissionOptions direct(WorldSpec world) {
        return new MissionOptions(world, null, null, null, "safety-first", 1).withLink(MissionOptions.Link.DIRECT)
                .withNoise(NoiseLevel.SMALL);
    }

    private static Missions.Run onDatabase(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            return run(new MissionOptions(crossing(SHORT_S), db.jdbcUrl(), db.user(), db.password(), "safety-first", 1)
                    .withNoise(NoiseLevel.SMALL), 2);
        }
    }

    private static String trace(Missions.Run run) throws Exception {
        return Files.readString(run.outDir().resolve("trace.jsonl"));
    }

    /** The report without the wall clock and the database's name. */
    private static MissionReport deterministic(MissionReport r) {
        return new MissionReport(r.world(), r.success(), r.outcome(), r.strategy(), "-", r.checkpointsReached(),
                r.checkpointsTotal(), r.simTimeS(), 0, 0, r.controlSteps(), r.engineIterations(), r.distanceM(),
                r.collisions(), r.robotCollisions(), r.minClearanceM(), r.minBattery(), r.finalBattery(), r.recharges(),
                r.commandWins(), r.ruleFailures(), r.poseError(), null, r.robots());
    }

    @Test
    void everyRobotRunsItsOwnMissionAndTheTraceAndReportSayWhich() throws Exception {
        Missions.Run run = run(direct(crossing()), 1);
        MissionReport report = run.report();
        assertThat(report.robots()).extracting(RobotReport::id).containsExactly(1, 2, 5);
        assertThat(report.checkpointsTotal()).isEqualTo(4);
        assertThat(report.checkpointsReached()).isEqualTo(report.robots().stream().mapToInt(RobotReport::checkpointsReached).sum());
        assertThat(report.collisions()).isEqualTo(report.robots().stream().mapToInt(RobotReport::collisions).sum());
        assertThat(report.robotCollisions()).isEqualTo(report.robots().stream().mapToInt(RobotReport::robotCollisions).sum());
        assertThat(report.minBattery()).isEqualTo(report.robots().stream().mapToDouble(RobotReport::minBattery).min().orElseThrow());
        assertThat(report.success()).isEqualTo(report.robots().stream().allMatch(RobotReport::success));
        // Each robot drove its own mission: every one reached at least its first checkpoint.
        assertThat(report.robots()).allSatisfy(r -> assertThat(r.checkpointsReached()).isPositive());
        for (RobotReport r : report.robots()) {
            if (r.outcome() == Outcome.MISSION_ACCOMPLISHED) {
                assertThat(r.endSimTimeS()).isLessThanOrEqualTo(report.simTimeS());
                assertThat(r.reason()).startsWith("every checkpoint reached at ");
            }
        }
        List<JsonObject> lines = Files.readAllLines(run.outDir().resolve("trace.jsonl")).stream()
                .map(l -> JsonParser.parseString(l).getAsJsonObject()).toList();
        assertThat(lines).extracting(l -> l.get("robot").getAsInt()).contains(1, 2, 5).allMatch(id -> id == 1 || id == 2 || id == 5);
        // A robot that accomplished its mission while others go on steps on, out of their way, until the run ends:
        // robot 1's lines go past its own end (10.1 s) up to the run's.
        RobotReport first = report.robots().get(0);
        double lastOfFirst = lines.stream().filter(l -> l.get("robot").getAsInt() == 1)
                .mapToDouble(l -> l.get("simTimeS").getAsDouble()).max().orElseThrow();
        assertThat(first.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(first.endSimTimeS()).isLessThan(report.simTimeS());
        assertThat(lastOfFirst).isGreaterThan(first.endSimTimeS()).isLessThanOrEqualTo(report.simTimeS());
        String svg = Files.readString(run.outDir().resolve("trajectory.svg"));
        assertThat(svg).contains("robot 1 end", "robot 2 end", "robot 5 end");
        assertThat(run.outDir().resolve("replay.html")).isNotEmptyFile();
    }

    @Test
    void oneOrTwoEngineThreadsGiveTheSameRunBitForBit() throws Exception {
        Missions.Run one = run(direct(crossing(SHORT_S)), 1);
        Missions.Run two = run(direct(crossing(SHORT_S)), 2);
        assertThat(trace(two)).isEqualTo(trace(one));
        assertThat(deterministic(two.report())).isEqualTo(deterministic(one.report()));
    }

    @Test
    void theDirectLinkAndH2GiveTheSameRun() throws Exception {
        Missions.Run direct = run(direct(crossing(SHORT_S)), 1);
        Missions.Run h2 = onDatabase(DatabaseKind.H2);
        assertThat(h2.report().outcome()).isEqualTo(Outcome.TIME_LIMIT);
        assertThat(h2.report().robots()).allSatisfy(r -> assertThat(r.distanceM()).isGreaterThan(1.0));
        assertThat(h2.report().database()).isEqualTo("h2");
        assertThat(trace(h2)).isEqualTo(trace(direct));
        assertThat(deterministic(h2.report())).isEqualTo(deterministic(direct.report()));
    }

    @Test
    void mariaDbGivesTheSameRunAsTheDirectLink() throws Exception {
        Missions.Run onMariaDb = onDatabase(DatabaseKind.MARIADB); // skipped without PROACTIVE_TEST_MARIADB_URL
        Missions.Run direct = run(direct(crossing(SHORT_S)), 1);
        assertThat(trace(onMariaDb)).isEqualTo(trace(direct));
        assertThat(deterministic(onMariaDb.report())).isEqualTo(deterministic(direct.report()));
    }
}
