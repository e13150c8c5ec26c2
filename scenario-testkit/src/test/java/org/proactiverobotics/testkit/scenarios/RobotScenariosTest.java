package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.testkit.ScenarioKit;

/** The five robot scenarios together: found by name, started in the paper's order, saved and resumed. */
class RobotScenariosTest {

    static final List<String> PAPER_ORDER = List.of(
            "DataAcquisition", "Localisation", "BatteryMonitor", "ReachDestination", "ObstacleAvoidance", "DecisionMaking");

    private static ScenarioKit.Builder allFive() {
        // named in another order: the kit starts them in the standard one
        return ScenarioKit.builder().builtIn("ObstacleAvoidance", "ReachDestination", "BatteryMonitor", "DataAcquisition");
    }

    @Test
    void startUpCreatesTheScenariosInThePapersOrderAndTheDecisionRunsLast() {
        try (ScenarioKit kit = allFive().start()) {
            List<String> order = kit.engine().engine().nextQueue().stream().map(Rule::scenario).distinct().toList();
            assertThat(order).containsExactlyElementsOf(PAPER_ORDER);
            kit.step(3);
            assertThat(kit.scheduled()).last().isEqualTo("DecisionMaking/ReadRobotCommands");
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void everyScenarioRuleSurvivesSaveAndResumeWithItsState(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); ScenarioKit kit = allFive().database(db.dataSource()).start()) {
            kit.mission().checkpoint(0, 3).station(-3, 0, 100);
            kit.robot().gps(0, 0).headingDeg(90).scan(1, 1, 1, 1, 1, 1, 1, 1).battery(90);
            kit.step(4);
            RobotEngine resumed = RobotEngine.builder().database(kit.database()).build();
            assertThat(resumed.resume()).isTrue();
            assertThat(resumed.engine().iteration()).isEqualTo(kit.engine().engine().iteration());
            assertThat(resumed.engine().nextQueue()).extracting(Rule::toString).containsExactlyElementsOf(kit.scheduled());
            assertThat(resumed.engine().memory().values()).isEqualTo(kit.memory().values());
            assertThat(resumed.slots()).isEqualTo(kit.engine().slots());
        }
    }
}
