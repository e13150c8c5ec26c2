package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.JdbcStateStore;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.ScenarioRegistry;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;

/** The five robot scenarios together: found by name, started in the paper's order, saved and resumed. */
class RobotScenariosTest {

    static final List<String> PAPER_ORDER = List.of(
            "DataAcquisition", "BatteryMonitor", "ReachDestination", "ObstacleAvoidance", "DecisionMaking");

    @Test
    void startUpCreatesTheScenariosInThePapersOrderAndTheDecisionRunsLast() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture(PAPER_ORDER.toArray(String[]::new))) {
            f.iterate(2);
            List<String> order = f.engine.nextQueue().stream().map(Rule::scenario).distinct().toList();
            assertThat(order).containsExactlyElementsOf(PAPER_ORDER);
            f.iterate(3);
            List<Rule> queue = f.engine.nextQueue();
            assertThat(queue.get(queue.size() - 1).name()).isEqualTo("ReadRobotCommands");
        }
    }

    @Test
    void everyScenarioRuleSurvivesSaveAndResumeWithItsState() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            ProactiveEngine first = engine(db);
            first.startFresh(ScenarioRegistry.load().startUp(PAPER_ORDER));
            for (int i = 0; i < 6; i++) {
                first.runIteration();
            }
            ProactiveEngine resumed = engine(db);
            resumed.start();
            assertThat(resumed.resumed()).isTrue();
            assertThat(resumed.iteration()).isEqualTo(first.iteration());
            assertThat(resumed.nextQueue()).extracting(Rule::name)
                    .containsExactlyElementsOf(first.nextQueue().stream().map(Rule::name).toList());
        }
    }

    private static ProactiveEngine engine(TestDatabase db) {
        JdbcRobotTables tables = new JdbcRobotTables(db.dataSource(), 1);
        return ProactiveEngine.builder().robotId(1).store(new JdbcStateStore(db.dataSource()))
                .service(SensorReadings.class, tables).service(SensorRequests.class, tables)
                .service(MissionTables.class, tables).service(StrategyTable.class, tables)
                .service(EngineComments.class, tables).service(DriveProfile.class, DriveProfile.DEFAULT).build();
    }
}
