package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.Outcome;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.robot.Strategy;

/** The fail-safe scenario end to end: a scenario's rule throws in the middle of a mission. */
class FailSafeEndToEndTest {

    @Test
    void obstacleAvoidanceFailingNearAnObstacleSendsNoAvoidanceCommandStopsTheRobotAndComesBack() throws Exception {
        double failFromS = 31.36; // (a step's time) the collision monitor vetoes commands from 31.488 s to 32.416 s, at the obstacle across the path
        double failUntilS = 31.9;
        AtomicBoolean failing = new AtomicBoolean();
        FaultInjection fault = new FaultInjection(ObstacleAvoidanceScenario.class, failing::get);
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Missions.Run run = Missions.run("obstacle-across-path", db, Strategy.SAFETY_FIRST,
                    sim -> failing.set(sim.simTimeS() >= failFromS && sim.simTimeS() < failUntilS), fault);
            MissionReport report = run.report();

            assertThat(report.ruleFailures()).isPositive();
            List<FaultInjection.Sent> sent = fault.sent;
            long firstFailureMs = (long) (failFromS * 1000);
            // From the failure until the fail-safe has restarted avoidance: not one avoidance command, and STOP
            // from the fail-safe (the robot does not drive on without its avoidance).
            FaultInjection.Sent firstAvoidanceAgain = sent.stream()
                    .filter(s -> s.simTimeMs() >= firstFailureMs && s.scenario().equals("ObstacleAvoidance"))
                    .findFirst().orElseThrow();
            // (the command sent in the failure's first step was decided before it, by a healthy scenario)
            FaultInjection.Sent firstDriveAgain = sent.stream()
                    .filter(s -> s.simTimeMs() > firstFailureMs && !s.command().equals("STOP")).findFirst().orElseThrow();
            List<FaultInjection.Sent> window = sent.stream()
                    .filter(s -> s.simTimeMs() > firstFailureMs && s.iteration() < firstDriveAgain.iteration()).toList();
            assertThat(firstAvoidanceAgain.simTimeMs()).as("back only once the fault is gone").isGreaterThan((long) (failUntilS * 1000));
            assertThat(firstDriveAgain.simTimeMs()).as("driving again only once the fault is gone")
                    .isGreaterThan((long) (failUntilS * 1000));
            assertThat(window).isNotEmpty().allSatisfy(s -> assertThat(s.command()).as(s.toString()).isEqualTo("STOP"));
            assertThat(window).anySatisfy(s -> assertThat(s.scenario()).isEqualTo("FailSafe"));
            assertThat(report.commandWins()).containsKey("FailSafe");
            // The robot was safe, and the restarted avoidance took it around the obstacle to the end.
            assertThat(report.collisions()).isZero();
            assertThat(report.outcome()).isEqualTo(Outcome.MISSION_ACCOMPLISHED);
            assertThat(run.trace()).anySatisfy(t -> assertThat(t.getAsJsonObject("suggestions").has("FailSafe")).isTrue());
        }
    }

    @Test
    void withoutFailuresTheFailSafeNeverActs() {
        MissionReport report = Missions.onH2("cluttered-arena").report();
        assertThat(report.ruleFailures()).isZero();
        assertThat(report.commandWins()).doesNotContainKey("FailSafe");
    }
}
