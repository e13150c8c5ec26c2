package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.testkit.ScenarioKit;

/** Scenario 1 alone: GetGPS, GetDS, GetIU, GetBattery, GetOdometry ask for data when theirs is missing or old. */
class DataAcquisitionScenarioTest {

    @Test
    void everySensorIsRequestedOnceUntilTheRobotAnswers() {
        try (ScenarioKit kit = ScenarioKit.builder().withDataAcquisition().start()) {
            kit.step(); // the robot publishes nothing: it answers nothing
            assertThat(kit.requestedSensors()).containsExactly("GPS", "DS", "IU", "BATTERY", "ODOMETRY");
            kit.step(5);
            assertThat(kit.requestedSensors()).as("no second request while one is pending").hasSize(5);
        }
    }

    @Test
    void aFreshReadingIsAskedForEveryIterationButTheBatteryOnlyWhenItsIntervalHasPassed() {
        try (ScenarioKit kit = ScenarioKit.builder().withDataAcquisition().timeStepMs(160).start()) {
            kit.step(); // t=0: nothing yet, everything requested
            kit.robot().gps(0, 0).headingDeg(0).scan(1, 1, 1, 1, 1, 1, 1, 1).battery(100).odometry(0, 0);
            kit.step(); // t=160: every request answered
            assertThat(kit.requestedSensors()).containsExactly("GPS", "DS", "IU", "ODOMETRY");

            kit.robot().silent(Sensor.BATTERY);
            kit.step(); // t=320: the battery reading of t=160 (interval 320 ms) is still recent
            assertThat(kit.requestedSensors()).containsExactly("GPS", "DS", "IU", "ODOMETRY");

            kit.step(); // t=480: now it is 320 ms old
            assertThat(kit.requestedSensors()).containsExactly("GPS", "DS", "IU", "BATTERY", "ODOMETRY");
        }
    }
}
