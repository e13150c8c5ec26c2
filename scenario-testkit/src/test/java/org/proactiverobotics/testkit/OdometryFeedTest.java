package org.proactiverobotics.testkit;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.WheelOdometry;

/** The scripted robot feeds wheel odometry to a scenario under test, and answers the data acquisition's requests for it. */
class OdometryFeedTest {

    /** A scenario reading odometry: STOP while the newest reading shows the wheels turning opposite ways. */
    static final class SpinGuardScenario implements Scenario {

        static final String NAME = "SpinGuard";

        @Override
        public String name() {
            return NAME;
        }

        @Override
        public List<Rule> firstRules() {
            return List.of(new Guard());
        }

        static final class Guard extends Rule {

            private transient WheelOdometry odometry;

            @Override
            public String scenario() {
                return NAME;
            }

            @Override
            protected void acquireConditionData(RuleContext ctx) {
                odometry = ctx.service(SensorReadings.class).newestOdometry().orElse(null);
            }

            @Override
            protected void actions(RuleContext ctx) {
                if (odometry != null && odometry.leftM() * odometry.rightM() < 0) {
                    ctx.suggest("STOP");
                }
            }

            @Override
            protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
                ctx.generate(this);
            }
        }
    }

    @Test
    void aScenarioUnderTestReadsTheOdometryTheScriptGives() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new SpinGuardScenario()).start()) {
            kit.step();
            assertThat(kit.suggestion(SpinGuardScenario.NAME)).as("no odometry yet").isNull();
            kit.robot().odometry(0.016, 0.016);
            kit.step();
            assertThat(kit.suggestion(SpinGuardScenario.NAME)).as("driving straight").isNull();
            kit.robot().odometry(-0.0064, 0.0064);
            kit.step();
            assertThat(kit.suggestion(SpinGuardScenario.NAME)).as("spinning on the spot").isEqualTo("STOP");
            kit.robot().odometry(0.01, 0.02);
            kit.step();
            assertThat(kit.suggestion(SpinGuardScenario.NAME)).isNull();
        }
    }

    @Test
    void theScriptWritesOneReadingAStepAndAnswersTheOdometryRequest() {
        try (ScenarioKit kit = ScenarioKit.builder().withDataAcquisition().start()) {
            kit.step();
            assertThat(kit.requestedSensors()).contains("ODOMETRY");
            kit.robot().odometry(0.02, -0.01);
            kit.step(3);
            assertThat(kit.requestedSensors()).as("asked every iteration, answered every step").containsExactly("GPS", "DS", "IU",
                    "BATTERY", "ODOMETRY");
            kit.robot().silent(Sensor.ODOMETRY);
            kit.step(2);
            assertThat(kit.requestedSensors()).as("silent: asked once, left pending").containsExactly("GPS", "DS", "IU",
                    "BATTERY", "ODOMETRY").hasSize(5);
            List<double[]> rows = odometryRows(kit);
            assertThat(rows).hasSize(3);
            assertThat(rows).allSatisfy(r -> assertThat(r).containsExactly(0.02, -0.01));
        }
    }

    private static List<double[]> odometryRows(ScenarioKit kit) {
        List<double[]> out = new java.util.ArrayList<>();
        try (var c = kit.database().getConnection(); var s = c.createStatement();
             var rs = s.executeQuery("SELECT left_m, right_m FROM odometry WHERE robot_id = " + ScenarioKit.ROBOT_ID + " ORDER BY sim_time_ms")) {
            while (rs.next()) {
                out.add(new double[] {rs.getDouble(1), rs.getDouble(2)});
            }
        } catch (java.sql.SQLException e) {
            throw new IllegalStateException(e);
        }
        return out;
    }
}
