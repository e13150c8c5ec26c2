package org.proactiverobotics.robot.link;

import java.util.List;

/**
 * The robot's answer to the pending requests of one control step: the readings taken (each
 * null / empty when not requested) and the requests they answer. A link writes it atomically:
 * every reading and every "answered" mark, or nothing.
 *
 * @param simTimeMs  the simulated time of the readings, milliseconds
 * @param gps        the GPS reading, or null
 * @param iu         the inertial unit reading, or null
 * @param distances  the distance sensors' readings (one per sensor), empty when not requested
 * @param battery    the battery reading, or null
 * @param odometry   the wheel odometry reading (travel since the previous one), or null
 * @param requestIds the ids of the requests this answers
 */
public record SensorAnswer(long simTimeMs, GpsReading gps, IuReading iu, List<DistanceReading> distances,
                           BatteryReading battery, OdometryReading odometry, long[] requestIds) {

    /**
     * An answer without odometry.
     *
     * @param simTimeMs  the simulated time of the readings, milliseconds
     * @param gps        the GPS reading, or null
     * @param iu         the inertial unit reading, or null
     * @param distances  the distance sensors' readings, empty when not requested
     * @param battery    the battery reading, or null
     * @param requestIds the ids of the requests this answers
     */
    public SensorAnswer(long simTimeMs, GpsReading gps, IuReading iu, List<DistanceReading> distances,
                        BatteryReading battery, long[] requestIds) {
        this(simTimeMs, gps, iu, distances, battery, null, requestIds);
    }

    /** @return how many readings (sensors) this answer carries */
    public int readingCount() {
        return (gps != null ? 1 : 0) + (iu != null ? 1 : 0) + (distances.isEmpty() ? 0 : 1) + (battery != null ? 1 : 0)
                + (odometry != null ? 1 : 0);
    }
}
