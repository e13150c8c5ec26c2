package org.proactiverobotics.robot.link;

/**
 * One pending request for fresh data, as the engine wrote it in {@code sensor_requests}.
 *
 * @param id     the request's id (grows with time)
 * @param sensor the requested sensor's name as written; see {@link org.proactiverobotics.protocol.Sensor#byName}
 */
public record SensorRequest(long id, String sensor) {
}
