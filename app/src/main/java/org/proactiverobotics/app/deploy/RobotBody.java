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
 * between the wheels, metres) an engine must assume for one robot, and whether other robots share
 * its world. The robot process writes it from the world file at the start of every run, as it
 * seeds {@code initial_pose}; the engine reads it when it takes up the run. So one engine process
 * can drive robots of different sizes, each as {@code run} drives it (its {@code --max-speed-mps} /
 * {@code --axle-width-m} are only the fallback for a robot whose process wrote no row, or an
 * override when given), and runs the traffic scenario, Yield, exactly for the robots of a world
 * with several, as {@code run} does.
 *
 * @param drive       the drive profile the robot's engine assumes
 * @param sharedWorld whether other robots share the robot's world (its engine then runs Yield)
 */
public record RobotBody(DriveProfile drive, boolean sharedWorld) {

    /**
     * @param robot       a world file's robot
     * @param sharedWorld whether its world has several robots
     * @return the body {@code run} gives its engine: its top speed, twice its radius between the wheels
     */
    public static RobotBody of(WorldSpec.Robot robot, boolean sharedWorld) {
        return new RobotBody(new DriveProfile(robot.maxSpeedMps(), 2 * robot.radiusM()), sharedWorld);
    }

    /**
     * Writes (or replaces) one robot's row.
     *
     * @param dataSource the shared database
     * @param robotId    the robot
     * @param body       its body
     * @throws SQLException when the row cannot be written (an old database without the table, say)
     */
    public static void write(DataSource dataSource, int robotId, RobotBody body) throws SQLException {
        try (Connection c = dataSource.getConnection()) {
            boolean auto = c.getAutoCommit();
            c.setAutoCommit(true);
            try (PreparedStatement update = c.prepareStatement(
                    "UPDATE robot_body SET max_speed_mps = ?, axle_width_m = ?, shared_world = ? WHERE robot_id = ?")) {
                update.setDouble(1, body.drive().maxSpeedMps());
                update.setDouble(2, body.drive().axleWidthM());
                update.setBoolean(3, body.sharedWorld());
                update.setInt(4, robotId);
                if (update.executeUpdate() == 0) {
                    try (PreparedStatement insert = c.prepareStatement(
                            "INSERT INTO robot_body (robot_id, max_speed_mps, axle_width_m, shared_world) VALUES (?, ?, ?, ?)")) {
                        insert.setInt(1, robotId);
                        insert.setDouble(2, body.drive().maxSpeedMps());
                        insert.setDouble(3, body.drive().axleWidthM());
                        insert.setBoolean(4, body.sharedWorld());
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
     * @return its row's body; empty when it has none or the row holds nonsense
     * @throws SQLException when it cannot be read
     */
    public static Optional<RobotBody> read(DataSource dataSource, int robotId) throws SQLException {
        try (Connection c = dataSource.getConnection();
             PreparedStatement ps = c.prepareStatement(
                     "SELECT max_speed_mps, axle_width_m, shared_world FROM robot_body WHERE robot_id = ?")) {
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
                return Optional.of(new RobotBody(new DriveProfile(speed, axle), rs.getBoolean(3)));
            }
        }
    }
}
