package org.proactiverobotics.engine.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Scenario 1 alone: GetGPS, GetDS, GetIU, GetBattery ask for data when theirs is missing or old. */
class DataAcquisitionScenarioTest {

    @Test
    void everySensorIsRequestedOnceUntilTheRobotAnswers() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DataAcquisition")) {
            f.iterate(3);
            assertThat(f.pendingSensors()).containsExactly("GPS", "DS", "IU", "BATTERY");
            f.iterate(5);
            assertThat(f.pendingSensors()).as("no second request while one is pending").hasSize(4);
        }
    }

    @Test
    void aFreshReadingIsAskedForEveryIterationButTheBatteryOnlyWhenItsIntervalHasPassed() throws Exception {
        try (RobotTablesFixture f = new RobotTablesFixture("DataAcquisition")) {
            f.iterate(3);
            f.gps(0, 0, 0);
            f.battery(0, 100, false);
            f.answerAll(0);
            f.iterate(1);
            assertThat(f.pendingSensors()).containsExactly("GPS", "DS", "IU");

            f.gps(160, 0, 0); // 160 ms later: the battery reading (interval 320 ms) is still recent
            f.answerAll(160);
            f.iterate(1);
            assertThat(f.pendingSensors()).containsExactly("GPS", "DS", "IU");

            f.gps(320, 0, 0);
            f.answerAll(320);
            f.iterate(1);
            assertThat(f.pendingSensors()).containsExactly("GPS", "DS", "IU", "BATTERY");
        }
    }
}
