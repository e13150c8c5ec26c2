package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.Optional;
import javax.sql.DataSource;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The {@code robot_body} row: the drive profile (top wheel speed, metres per second; distance
 * between the wheels, metres) an engine must assume for one robot. The robot process writes it
 * from the world file at the start of every run, as it seeds {@code initial_pose}; the engine
 * reads it when it takes up the run. So one engine process can drive robots of different sizes,
 * each as {@code run} drives it, and its {@code --max-speed-mps} / {@code --axle-width-m} are only
 * the fallback for a robot whose process wrote no row (or an override when given).
 */
public final class RobotBody {

    private RobotBody() {
    }

    /**
     * @param robot a world file's robot
     * @return the drive profile {@code run} gives its engine: its top speed, twice its radius between the wheels
     */
    public static DriveProfile of(WorldSpec.Robot robot) {
        return new DriveProfile(robot.maxSpeedMps(), 2 * robot.radiusM());
    }

    /**
     * Writes (or replaces) one robot's row.
     *
     * @param dataSource the shared database
     * @param robotId    the robot
     * @param drive      its drive profile
     * @throws SQLException when the row cannot be written (an old database without the table, say)
     */
    public static void write(DataSource dataSource, int robotId, DriveProfile drive) throws SQLException {
        try (Connection c = dataSource.getConnection()) {
            boolean auto = c.getAutoCommit();
            c.setAutoCommit(true);
            try (PreparedStatement update = c.prepareStatement(
                    "UPDATE robot_body SET max_speed_mps = ?, axle_width_m = ? WHERE robot_id = ?")) {
                update.setDouble(1, drive.maxSpeedMps());
                update.setDouble(2, drive.axleWidthM());
                update.setInt(3, robotId);
                if (update.executeUpdate() == 0) {
                    try (PreparedStatement insert = c.prepareStatement(
                            "INSERT INTO robot_body (robot_id, max_speed_mps, axle_width_m) VALUES (?, ?, ?)")) {
                        insert.setInt(1, robotId);
                        insert.setDouble(2, drive.maxSpeedMps());
                        insert.setDouble(3, drive.axleWidthM());
                        insert.executeUpdate();
                    }
                }
            } finally {
                c.setAutoCommit(auto);
            }
        }
    }

    /**
     * @param dataSource the shared database
     * @param robotId    the robot
     * @return its row's drive profile; empty when it has none or the row holds nonsense
     * @throws SQLException when it cannot be read
     */
    public static Optional<DriveProfile> read(DataSource dataSource, int robotId) throws SQLException {
        try (Connection c = dataSource.getConnection();
             PreparedStatement ps = c.prepareStatement("SELECT max_speed_mps, axle_width_m FROM robot_body WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                if (!rs.next()) {
                    return Optional.empty();
                }
                double speed = rs.getDouble(1);
                double axle = rs.getDouble(2);
                if (!(speed > 0) || !Double.isFinite(speed) || !(axle > 0) || !Double.isFinite(axle)) {
                    return Optional.empty(); // written by hand, not by a robot: the options are safer
                }
                return Optional.of(new DriveProfile(speed, axle));
            }
        }
    }
}
