package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import java.nio.file.Files;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/** The headless mission end to end: engine, robot controller and simulator through a real database. */
class MissionEndToEndTest {

    static List<String> bundledWorlds() {
        return WorldFiles.bundledNames();
    }

    @ParameterizedTest
    @MethodSource("bundledWorlds")
    void everyExampleWorldIsAccomplishedWithoutCollisionOrFlatBattery(String world) {
        MissionReport report = Missions.onH2(world).report();
        assertThat(report.outcome()).as(world).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        assertThat(report.checkpointsReached()).isEqualTo(report.checkpointsTotal()).isPositive();
        assertThat(report.collisions()).as("collisions in " + world).isZero();
        assertThat(report.minBattery()).as("lowest battery in " + world).isGreaterThan(0.0);
        assertThat(report.ruleFailures()).isZero();
        assertThat(report.engineIterations()).isEqualTo(report.controlSteps());
        // commandWins counts the commands the robot got: one a step once the first decision is sent.
        long commands = report.commandWins().values().stream().mapToLong(Long::longValue).sum();
        assertThat(commands).isBetween(report.controlSteps() - 3, report.controlSteps());
    }

    @Test
    void theLowBatteryWorldRechargesBecauseItMustAndTheReferenceWorldDoesNot() {
        MissionReport low = Missions.onH2("low-battery").report();
        assertThat(low.recharges()).isGreaterThanOrEqualTo(1);
        assertThat(low.commandWins()).containsKey("BatteryMonitor");
        // The route is longer than the initial charge allows: without the recharge it would fail.
        double initial = WorldFiles.bundled("low-battery").battery().initial();
        double drain = WorldFiles.bundled("low-battery").battery().drainPerMeter();
        assertThat(low.distanceM() * drain).isGreaterThan(initial);

        MissionReport reference = Missions.onH2("reference-arena").report();
        assertThat(reference.recharges()).isZero();
        assertThat(reference.commandWins()).doesNotContainKey("BatteryMonitor");
    }

    @Test
    void aBatteryThatSufficesIsNotRechargedOnTheWay() throws Exception {
        // The low-battery world's tour costs about 35 % at 2 %/m; 60 % is tight but enough.
        WorldSpec low = WorldFiles.bundled("low-battery");
        WorldSpec enough = low.withBattery(new WorldSpec.Battery(60.0, low.battery().drainPerMeter(),
                low.battery().rechargeTo(), low.battery().rechargeRatePerS()));
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            MissionReport report = new Mission(new MissionOptions(enough, db.jdbcUrl(), db.user(), db.password(),
                    Strategy.SAFETY_FIRST, 1)).run(Files.createTempDirectory("enough-battery-"));
            assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
            assertThat(report.recharges()).isZero();
            assertThat(report.minBattery()).isBetween(0.0, 60.0 - 30.0);
        }
    }

    @Test
    void obstacleAvoidanceGetsAroundObstaclesInTheClutteredArena() {
        MissionReport report = Missions.onH2("cluttered-arena").report();
        assertThat(report.commandWins().get("ObstacleAvoidance")).isPositive();
        assertThat(report.commandWins().get("ReachDestination")).isGreaterThan(report.commandWins().get("ObstacleAvoidance"));
        assertThat(report.minClearanceM()).isPositive();
    }

    @Test
    void aStrategyChangedWhileRunningDecidesTheNextIterations() throws Exception {
        double switchAtS = 31.4; // under safety-first the collision monitor vetoes the destination's commands from 31.488 s
        double switchBackAtS = 34.0;
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            JdbcRobotTables strategyFromOutside = new JdbcRobotTables(db.dataSource(), 1);
            AtomicBoolean switched = new AtomicBoolean();
            AtomicBoolean switchedBack = new AtomicBoolean();
            Missions.Run run = Missions.run("obstacle-across-path", db, Strategy.SAFETY_FIRST, sim -> {
                if (!switched.get() && sim.simTimeS() >= switchAtS) {
                    switched.set(true);
                    strategyFromOutside.write(Strategy.named(Strategy.DESTINATION_FIRST).rows(RobotEngine.freshSlots(ScenarioPlugins.none())));
                } else if (!switchedBack.get() && sim.simTimeS() >= switchBackAtS) {
                    switchedBack.set(true);
                    strategyFromOutside.write(Strategy.named(Strategy.SAFETY_FIRST).rows(RobotEngine.freshSlots(ScenarioPlugins.none())));
                }
            });
            List<JsonObject> trace = run.trace();
            // Decisions strictly inside the destination-first window (one step of slack each side).
            List<JsonObject> during = trace.stream()
                    .filter(t -> t.get("simTimeS").getAsDouble() > switchAtS + 0.05
                            && t.get("simTimeS").getAsDouble() < switchBackAtS - 0.05).toList();
            List<JsonObject> before = trace.stream().filter(t -> t.get("simTimeS").getAsDouble() < switchAtS).toList();
            assertThat(during).isNotEmpty().allSatisfy(t -> {
                JsonObject suggestions = t.getAsJsonObject("suggestions");
                String expected = suggestions.has("ReachDestination") ? "ReachDestination" : "DecisionMaking";
                assertThat(t.get("winner").getAsString()).as(t.toString()).isEqualTo(expected);
            });
            // ... even where avoidance had something to say (it vetoed the destination's command), which safety-first obeys.
            assertThat(during).anySatisfy(t -> assertThat(t.getAsJsonObject("suggestions").has("ObstacleAvoidance")).isTrue());
            assertThat(before).allSatisfy(t -> assertThat(t.getAsJsonObject("priorities").get("ObstacleAvoidance").getAsInt())
                    .isEqualTo(3));
            List<JsonObject> after = trace.stream().filter(t -> t.get("simTimeS").getAsDouble() > switchBackAtS + 0.05).toList();
            assertThat(after).allSatisfy(t -> {
                if (t.getAsJsonObject("suggestions").has("ObstacleAvoidance")) {
                    assertThat(t.get("winner").getAsString()).isEqualTo("ObstacleAvoidance");
                }
            });
            assertThat(run.report().outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
        }
    }

    @Test
    void theSameWorldAndSeedGiveTheSameRunBitForBit() throws Exception {
        Missions.Run first = Missions.onH2("reference-arena");
        Missions.Run second = Missions.run("reference-arena", DatabaseKind.H2, Strategy.SAFETY_FIRST, sim -> { });
        assertThat(second.deterministicPart()).isEqualTo(first.deterministicPart());
        assertThat(Files.readString(second.outDir().resolve("trace.jsonl")))
                .isEqualTo(Files.readString(first.outDir().resolve("trace.jsonl")));
        assertThat(Files.readString(second.outDir().resolve("trajectory.svg")))
                .isEqualTo(Files.readString(first.outDir().resolve("trajectory.svg")));
    }

    @Test
    void aRunOnMariaDbGivesTheSameReportAsOnH2() throws Exception {
        AtomicLong steps = new AtomicLong();
        Missions.Run onMariaDb = Missions.run("reference-arena", DatabaseKind.MARIADB, Strategy.SAFETY_FIRST,
                sim -> steps.incrementAndGet());
        assertThat(onMariaDb.report().database()).isEqualTo("mariadb");
        assertThat(onMariaDb.deterministicPart()).isEqualTo(Missions.onH2("reference-arena").deterministicPart());
        assertThat(Files.readString(onMariaDb.outDir().resolve("trace.jsonl")))
                .isEqualTo(Files.readString(Missions.onH2("reference-arena").outDir().resolve("trace.jsonl")));
        assertThat(steps.get()).isEqualTo(onMariaDb.report().controlSteps());
    }
}
