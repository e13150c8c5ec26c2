package org.proactiverobotics.engine.tables;

/**
 * The sensors the engine can ask the robot to read, as named in {@code sensor_requests.sensor}:
 * the scenarios' face of {@link org.proactiverobotics.protocol.Sensor}, the protocol's one list,
 * kept here because plug-in scenarios name it; {@link #word()} is what goes in the table.
 */
public enum Sensor {
    /** GPS: {@code gps_stored_values}. */
    GPS,
    /** Inertial unit: {@code iudata}. */
    IU,
    /** Distance sensors: {@code distance_sensor_data}. */
    DS,
    /** Battery: {@code battery_level}. */
    BATTERY,
    /** Wheel odometry: {@code odometry}. */
    ODOMETRY;

    private final org.proactiverobotics.protocol.Sensor word = org.proactiverobotics.protocol.Sensor.valueOf(name());

    /** @return the protocol's sensor of the same name (the class does not load if the protocol lacks one) */
    public org.proactiverobotics.protocol.Sensor word() {
        return word;
    }
}
