package org.proactiverobotics.engine.tables;

/** The engine's requests for fresh sensor data ({@code sensor_requests}). */
public interface SensorRequests {

    /** @return whether a request for this sensor still waits for the robot's answer */
    boolean pending(Sensor sensor);

    /**
     * Asks the robot for a fresh reading.
     *
     * @param sensor    which sensor
     * @param iteration the engine iteration asking
     */
    void request(Sensor sensor, long iteration);
}
