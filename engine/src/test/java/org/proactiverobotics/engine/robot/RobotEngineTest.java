package org.proactiverobotics.engine.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.engine.testscenarios.Alpha;

/** The one wiring: start order, slots, and plug-ins that are also on the class path. */
class RobotEngineTest {

    @Test
    void pluginsStartAfterTheBuiltInsThatFindTheWayAndBeforeTheCollisionMonitorFailSafeAndTheDecision() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Schema.apply(db.dataSource());
            RobotEngine engine = RobotEngine.builder().database(db.dataSource()).plugins(ScenarioPlugins.of(new Alpha())).build();
            assertThat(engine.scenarios()).containsExactly("DataAcquisition", "Mapping", "BatteryMonitor", "ReachDestination",
                    "Alpha", "ObstacleAvoidance", "FailSafe", "DecisionMaking");
            engine.startFresh();
            assertThat(engine.slots()).containsExactly(Map.entry("ReachDestination", 0), Map.entry("BatteryMonitor", 1),
                    Map.entry("ObstacleAvoidance", 2), Map.entry("Alpha", 3));
            assertThat(RobotEngine.freshSlots(ScenarioPlugins.of(new Alpha()))).isEqualTo(Map.of("ReachDestination", 0,
                    "BatteryMonitor", 1, "ObstacleAvoidance", 2, "Alpha", 3));
        }
    }

    @Test
    void aPluginAlsoListedOnTheClassPathIsTakenOnceAsThePlugin() throws Exception {
        // Alpha is in this module's test META-INF/services, as a user's scenario is in their own project's tests.
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Schema.apply(db.dataSource());
            Alpha given = new Alpha();
            RobotEngine engine = RobotEngine.builder().database(db.dataSource()).plugins(ScenarioPlugins.of(given)).build();
            assertThat(engine.registry().get("Alpha")).isSameAs(given);
        }
    }

    @Test
    void onlyStartsTheNamedScenariosInTheStandardOrderAndRefusesAnUnknownOne() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Schema.apply(db.dataSource());
            RobotEngine engine = RobotEngine.builder().database(db.dataSource())
                    .only("DecisionMaking", "ObstacleAvoidance").build();
            assertThat(engine.scenarios()).containsExactly("ObstacleAvoidance", "DecisionMaking");
            assertThatThrownBy(() -> RobotEngine.builder().database(db.dataSource()).only("Nope").build())
                    .hasMessageContaining("unknown scenario 'Nope'");
            assertThatThrownBy(() -> ScenarioPlugins.of(new Alpha(), new Alpha())).isInstanceOf(PluginException.class)
                    .hasMessageContaining("'Alpha'");
        }
    }
}
