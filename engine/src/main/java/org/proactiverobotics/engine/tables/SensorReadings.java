package org.proactiverobotics.engine.tables;

import java.util.Optional;

/** The newest sensor readings the robot wrote for this robot. */
public interface SensorReadings {

    /** @return the newest GPS reading, if any */
    Optional<GpsFix> newestGps();

    /** @return the newest inertial-unit reading, if any */
    Optional<Heading> newestHeading();

    /** @return the newest distance-sensor reading, if any */
    Optional<DistanceScan> newestScan();

    /** @return the newest battery reading, if any */
    Optional<BatteryState> newestBattery();

    /** @return the newest wheel odometry reading (the travel since the one before it), if any */
    Optional<WheelOdometry> newestOdometry();

    /** @return the simulated time of the newest reading of a sensor, or -1 when there is none */
    long newestSimTimeMs(Sensor sensor);

    /**
     * @return the robot's clock as the engine sees it: the newest time of a GPS, inertial-unit or
     *         odometry reading (indoors, with no GPS, the others keep it), simulated ms; -1 before any
     */
    default long robotClockMs() {
        return Math.max(newestSimTimeMs(Sensor.GPS), Math.max(newestSimTimeMs(Sensor.IU), newestSimTimeMs(Sensor.ODOMETRY)));
    }
}
