package org.proactiverobotics.engine.tables;

/** The sensors the engine can ask the robot to read, as named in {@code sensor_requests.sensor}. */
public enum Sensor {
    /** GPS: {@code gps_stored_values}. */
    GPS,
    /** Inertial unit: {@code iudata}. */
    IU,
    /** Distance sensors: {@code distance_sensor_data}. */
    DS,
    /** Battery: {@code battery_level}. */
    BATTERY
}
