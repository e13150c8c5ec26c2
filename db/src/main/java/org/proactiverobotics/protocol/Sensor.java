package org.proactiverobotics.protocol;

import java.util.Optional;

/**
 * The sensors the engine may ask the robot for, by the names it writes in
 * {@code sensor_requests.sensor}.
 */
public enum Sensor {
    /** Position, to {@code gps_stored_values}. */
    GPS,
    /** Inertial unit (roll, pitch, yaw), to {@code iudata}. */
    IU,
    /** Every distance sensor, one row each, to {@code distance_sensor_data}. */
    DS,
    /** Battery level, to {@code battery_level}. */
    BATTERY,
    /** Wheel odometry (each wheel's travel since the previous reading), to {@code odometry}. */
    ODOMETRY;

    /**
     * The sensor a request names, exactly (upper case, no padding).
     *
     * @param name the text of {@code sensor_requests.sensor}
     * @return the sensor, or empty when the name is unknown
     */
    public static Optional<Sensor> byName(String name) {
        if (name != null) {
            for (Sensor s : values()) {
                if (s.name().equals(name)) {
                    return Optional.of(s);
                }
            }
        }
        return Optional.empty();
    }
}
