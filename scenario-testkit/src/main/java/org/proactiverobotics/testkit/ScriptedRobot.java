package org.proactiverobotics.testkit;

import java.util.Arrays;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;
import org.proactiverobotics.engine.tables.Sensor;

/**
 * The robot's half of a scenario test, played by the script: the readings its sensors give
 * now. At every {@link ScenarioKit#step()} the robot writes each reading it publishes at that
 * step's simulated time and marks the pending requests for those sensors answered, as the real
 * robot does; a sensor never given a reading, or made {@link #silent}, writes nothing and
 * answers nothing, so its newest reading grows old (missing data). Values are written as given,
 * garbage included (a NaN, a negative distance): what the scenario makes of them is the test.
 *
 * <p>Units: metres, degrees or radians as named, percent (0 to 100).
 */
public final class ScriptedRobot {

    /** The directions of the eight distance sensors, degrees from the heading, rightmost first. */
    public static final double[] SENSOR_ANGLES_DEG = {-90, -45, -20, -8, 8, 20, 45, 90};
    /** The range of the distance sensors, metres: a ray that hits nothing reads this. */
    public static final double SENSOR_RANGE_M = 1.0;

    private final int robotId;
    private final KitDatabase db;
    private final Set<Sensor> silent = EnumSet.noneOf(Sensor.class);

    private double[] gps;
    private Double yawRad;
    private double[] distances;
    private Double batteryPct;
    private boolean charging;
    private double[] wheelTravel;

    ScriptedRobot(int robotId, KitDatabase db) {
        this.robotId = robotId;
        this.db = db;
    }

    /**
     * @param xM the robot's position, metres
     * @param yM the robot's position, metres
     * @return this robot; GPS publishes again if it was silent
     */
    public ScriptedRobot gps(double xM, double yM) {
        gps = new double[] {xM, yM};
        silent.remove(Sensor.GPS);
        return this;
    }

    /**
     * @param yawDeg the heading, degrees: 0 faces +x, counter-clockwise positive (90 faces +y)
     * @return this robot; the inertial unit publishes again if it was silent
     */
    public ScriptedRobot headingDeg(double yawDeg) {
        return headingRad(Math.toRadians(yawDeg));
    }

    /**
     * @param yawRad the heading, radians: 0 faces +x, counter-clockwise positive
     * @return this robot; the inertial unit publishes again if it was silent
     */
    public ScriptedRobot headingRad(double yawRad) {
        this.yawRad = yawRad;
        silent.remove(Sensor.IU);
        return this;
    }

    /**
     * @param distancesM what the eight distance sensors read, metres, in the order of
     *                   {@link #SENSOR_ANGLES_DEG} (rightmost first); {@value #SENSOR_RANGE_M}
     *                   is free space
     * @return this robot; the distance sensors publish again if they were silent
     * @throws IllegalArgumentException when there are not eight distances
     */
    public ScriptedRobot scan(double... distancesM) {
        if (distancesM.length != SENSOR_ANGLES_DEG.length) {
            throw new IllegalArgumentException("the robot has " + SENSOR_ANGLES_DEG.length
                    + " distance sensors (rightmost first); got " + distancesM.length + " distances: " + Arrays.toString(distancesM));
        }
        distances = distancesM.clone();
        silent.remove(Sensor.DS);
        return this;
    }

    /**
     * @param levelPct the battery level, percent (0 to 100), not charging
     * @return this robot; the battery publishes again if it was silent
     */
    public ScriptedRobot battery(double levelPct) {
        return battery(levelPct, false);
    }

    /**
     * @param levelPct the battery level, percent (0 to 100)
     * @param charging whether the robot is charging at the station
     * @return this robot; the battery publishes again if it was silent
     */
    public ScriptedRobot battery(double levelPct, boolean charging) {
        this.batteryPct = levelPct;
        this.charging = charging;
        silent.remove(Sensor.BATTERY);
        return this;
    }

    /**
     * The wheel odometry reading: each wheel's travel since the previous odometry reading. Every
     * step writes this same travel until it is given another (a robot whose wheels keep their
     * speeds); set it to 0, 0 for a robot standing still.
     *
     * @param leftM  the left wheel's travel since the previous reading, metres, positive forwards
     * @param rightM the right wheel's travel since the previous reading, metres, positive forwards
     * @return this robot; the odometry publishes again if it was silent
     */
    public ScriptedRobot odometry(double leftM, double rightM) {
        wheelTravel = new double[] {leftM, rightM};
        silent.remove(Sensor.ODOMETRY);
        return this;
    }

    /**
     * Stops these sensors publishing (a broken wire, a dead driver): from the next step their
     * newest reading grows old and their requests stay pending. Giving a sensor a new reading
     * makes it publish again.
     *
     * @param sensors the sensors that fall silent
     * @return this robot
     */
    public ScriptedRobot silent(Sensor... sensors) {
        for (Sensor s : sensors) {
            silent.add(Objects.requireNonNull(s));
        }
        return this;
    }

    /**
     * @param sensor a sensor
     * @return whether it writes a reading (and answers its requests) at the next step
     */
    public boolean publishes(Sensor sensor) {
        if (silent.contains(sensor)) {
            return false;
        }
        return switch (sensor) {
            case GPS -> gps != null;
            case IU -> yawRad != null;
            case DS -> distances != null;
            case BATTERY -> batteryPct != null;
            case ODOMETRY -> wheelTravel != null;
        };
    }

    /** The robot's sensing of one control step: its readings, then its answers. */
    void publish(long simTimeMs) {
        if (publishes(Sensor.GPS)) {
            db.update("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (?, ?, ?, ?)",
                    robotId, simTimeMs, gps[0], gps[1]);
        }
        if (publishes(Sensor.IU)) {
            db.update("INSERT INTO iudata (robot_id, sim_time_ms, roll_rad, pitch_rad, yaw_rad) VALUES (?, ?, 0, 0, ?)",
                    robotId, simTimeMs, yawRad);
        }
        if (publishes(Sensor.DS)) {
            for (int i = 0; i < distances.length; i++) {
                db.update("INSERT INTO distance_sensor_data (robot_id, sim_time_ms, sensor_index, angle_rad, distance_m, range_m)"
                        + " VALUES (?, ?, ?, ?, ?, ?)", robotId, simTimeMs, i, Math.toRadians(SENSOR_ANGLES_DEG[i]),
                        distances[i], SENSOR_RANGE_M);
            }
        }
        if (publishes(Sensor.BATTERY)) {
            db.update("INSERT INTO battery_level (robot_id, sim_time_ms, level_pct, charging) VALUES (?, ?, ?, ?)",
                    robotId, simTimeMs, batteryPct, charging);
        }
        if (publishes(Sensor.ODOMETRY)) {
            db.update("INSERT INTO odometry (robot_id, sim_time_ms, left_m, right_m) VALUES (?, ?, ?, ?)",
                    robotId, simTimeMs, wheelTravel[0], wheelTravel[1]);
        }
        for (Sensor s : Sensor.values()) {
            if (publishes(s)) {
                db.update("UPDATE sensor_requests SET answered_sim_time_ms = ?"
                        + " WHERE robot_id = ? AND sensor = ? AND answered_sim_time_ms IS NULL", simTimeMs, robotId, s.name());
            }
        }
    }
}
