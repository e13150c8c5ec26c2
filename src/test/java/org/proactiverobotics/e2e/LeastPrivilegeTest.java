package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.Main;
import picocli.CommandLine;

/**
 * The two database users the compose init creates (deploy/mysql-init/02-users.sh filling
 * deploy/users.sql), on MariaDB: each writes only its own tables, neither may drop, alter,
 * create or grant; {@code db users} creates the very same grants.
 */
class LeastPrivilegeTest {

    private static Deployment deployment;

    @BeforeAll
    static void deploy() throws Exception {
        deployment = Deployment.create();
    }

    @AfterAll
    static void tearDown() throws Exception {
        if (deployment != null) {
            deployment.close();
        }
    }

    private void asRobot(String sql) throws SQLException {
        deployment.executeAs(deployment.robotUser, Deployment.ROBOT_PASSWORD, sql);
    }

    private void asEngine(String sql) throws SQLException {
        deployment.executeAs(deployment.engineUser, Deployment.ENGINE_PASSWORD, sql);
    }

    @Test
    void theRobotMayNotWriteCommands() {
        assertThatThrownBy(() -> asRobot("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) "
                + "VALUES (1, 1, 0, 'Forged', 'FORWARD 0.5')"))
                .isInstanceOf(SQLException.class).hasMessageContaining("denied");
    }

    @Test
    void theEngineMayNotWriteReadings() {
        assertThatThrownBy(() -> asEngine("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (1, 0, 0, 0)"))
                .isInstanceOf(SQLException.class).hasMessageContaining("denied");
    }

    @Test
    void eachWritesItsOwnTablesAndReadsTheOthers() throws Exception {
        asRobot("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (99, 0, 1, 2)");
        asRobot("SELECT * FROM engine_comments WHERE robot_id = 99");
        asEngine("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (99, 1, 0, 'Test', 'STOP')");
        asEngine("SELECT * FROM gps_stored_values WHERE robot_id = 99");
        asEngine("UPDATE checkpoints SET reached = TRUE WHERE robot_id = 99");
        assertThatThrownBy(() -> asRobot("UPDATE checkpoints SET reached = TRUE WHERE robot_id = 99"))
                .hasMessageContaining("denied");
        assertThatThrownBy(() -> asRobot("INSERT INTO strategy (robot_id, slot, scenario, priority, strategy_name) "
                + "VALUES (99, 0, 'X', 1, 'x')")).hasMessageContaining("denied");
        assertThatThrownBy(() -> asEngine("INSERT INTO robot_clock (robot_id, run_id, step, sim_time_ms, timing, state) "
                + "VALUES (99, 1, 0, 0, 'sync', 'RUNNING')")).hasMessageContaining("denied");
        assertThatThrownBy(() -> asRobot("INSERT INTO engine_clock (robot_id, run_id, step, iteration) VALUES (99, 1, 0, 0)"))
                .hasMessageContaining("denied");
        // the leases are the engines' alone: the robot may not even see who serves it, the engine may not delete one
        asEngine("INSERT INTO engine_lease (robot_id, owner, epoch, expires_at) VALUES (99, 'e', 1, CURRENT_TIMESTAMP(3))");
        asEngine("UPDATE engine_lease SET epoch = 2 WHERE robot_id = 99");
        assertThatThrownBy(() -> asRobot("SELECT * FROM engine_lease")).hasMessageContaining("denied");
        assertThatThrownBy(() -> asRobot("UPDATE engine_lease SET owner = 'r' WHERE robot_id = 99")).hasMessageContaining("denied");
        assertThatThrownBy(() -> asEngine("DELETE FROM engine_lease WHERE robot_id = 99")).hasMessageContaining("denied");
        // Column grants: the engine may only mark checkpoints, the robot may only mark requests answered.
        assertThatThrownBy(() -> asEngine("UPDATE checkpoints SET x_m = 0 WHERE robot_id = 99"))
                .hasMessageContaining("denied");
        asRobot("UPDATE sensor_requests SET answered_sim_time_ms = 0 WHERE robot_id = 99");
        assertThatThrownBy(() -> asRobot("UPDATE sensor_requests SET sensor = 'GPS' WHERE robot_id = 99"))
                .hasMessageContaining("denied");
        assertThatThrownBy(() -> asRobot("DELETE FROM sensor_requests WHERE robot_id = 99"))
                .hasMessageContaining("denied");
    }

    @Test
    void theRobotWritesAndPrunesOdometryTheEngineOnlyReadsIt() throws Exception {
        asRobot("INSERT INTO odometry (robot_id, sim_time_ms, left_m, right_m) VALUES (98, 32, 0.016, 0.016)");
        asEngine("SELECT left_m, right_m FROM odometry WHERE robot_id = 98");
        assertThatThrownBy(() -> asEngine("INSERT INTO odometry (robot_id, sim_time_ms, left_m, right_m) VALUES (98, 64, 1, 1)"))
                .isInstanceOf(SQLException.class).hasMessageContaining("denied");
        assertThatThrownBy(() -> asEngine("UPDATE odometry SET left_m = 0 WHERE robot_id = 98"))
                .isInstanceOf(SQLException.class).hasMessageContaining("denied");
        assertThatThrownBy(() -> asEngine("DELETE FROM odometry WHERE robot_id = 98"))
                .isInstanceOf(SQLException.class).hasMessageContaining("denied");
        assertThatThrownBy(() -> asRobot("UPDATE odometry SET left_m = 0 WHERE robot_id = 98"))
                .isInstanceOf(SQLException.class).hasMessageContaining("denied");
        asRobot("DELETE FROM odometry WHERE robot_id = 98"); // retention, and a new run starting clean
    }

    @Test
    void theEngineAloneWritesItsPoseEstimateTheRobotAloneSeedsTheInitialPose() throws Exception {
        asEngine("INSERT INTO pose_estimate (robot_id, sim_time_ms, x_m, y_m, yaw_rad, var_x, var_y, var_yaw, cov_xy, cov_x_yaw,"
                + " cov_y_yaw) VALUES (97, 32, 1, 2, 0, 0, 0, 0, 0, 0, 0)");
        asRobot("INSERT INTO initial_pose (robot_id, x_m, y_m, yaw_rad) VALUES (97, 1, 2, 0)");
        asEngine("SELECT x_m FROM initial_pose WHERE robot_id = 97");
        assertThatThrownBy(() -> asRobot("SELECT x_m FROM pose_estimate")).hasMessageContaining("denied");
        assertThatThrownBy(() -> asRobot("INSERT INTO pose_estimate (robot_id, sim_time_ms, x_m, y_m, yaw_rad, var_x, var_y,"
                + " var_yaw, cov_xy, cov_x_yaw, cov_y_yaw) VALUES (97, 64, 0, 0, 0, 0, 0, 0, 0, 0, 0)")).hasMessageContaining("denied");
        assertThatThrownBy(() -> asEngine("UPDATE pose_estimate SET x_m = 0 WHERE robot_id = 97")).hasMessageContaining("denied");
        assertThatThrownBy(() -> asEngine("INSERT INTO initial_pose (robot_id, x_m, y_m, yaw_rad) VALUES (96, 0, 0, 0)"))
                .hasMessageContaining("denied");
        asEngine("DELETE FROM pose_estimate WHERE robot_id = 97"); // pruning, and a new run starting clean
    }

    @Test
    void theRobotAloneWritesItsBodyTheEngineReadsIt() throws Exception {
        asRobot("INSERT INTO robot_body (robot_id, max_speed_mps, axle_width_m) VALUES (95, 0.35, 0.32)");
        asRobot("UPDATE robot_body SET max_speed_mps = 0.4 WHERE robot_id = 95"); // each run writes it again
        asEngine("SELECT max_speed_mps FROM robot_body WHERE robot_id = 95");
        assertThatThrownBy(() -> asEngine("UPDATE robot_body SET max_speed_mps = 9 WHERE robot_id = 95"))
                .hasMessageContaining("denied");
        assertThatThrownBy(() -> asRobot("DELETE FROM robot_body WHERE robot_id = 95")).hasMessageContaining("denied");
    }

    @Test
    void neitherMayDropAlterCreateOrGrant() {
        for (String user : List.of("engine", "robot")) {
            for (String sql : List.of("DROP TABLE engine_comments", "ALTER TABLE gps_stored_values ADD COLUMN x INT",
                    "CREATE TABLE intruder (id INT)", "GRANT SELECT ON engine_state TO '" + deployment.robotUser + "'@'%'",
                    "DELETE FROM mysql.user")) {
                assertThatThrownBy(() -> {
                    if (user.equals("engine")) {
                        asEngine(sql);
                    } else {
                        asRobot(sql);
                    }
                }).as(user + ": " + sql).isInstanceOf(SQLException.class);
            }
        }
    }

    @Test
    void theViewerMayReadWhatWatchShowsAndNothingElseNorWriteAnything() throws Exception {
        for (String table : List.of("engine_comments", "gps_stored_values", "iudata", "distance_sensor_data",
                "battery_level", "odometry", "checkpoints", "recharge_station", "rule_failures", "strategy")) {
            asViewer("SELECT COUNT(*) FROM " + table);
        }
        for (String sql : List.of("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command)"
                        + " VALUES (1, 1, 0, 'X', 'STOP')", "DELETE FROM strategy", "UPDATE checkpoints SET reached = TRUE",
                "INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (1, 0, 0, 0)",
                "INSERT INTO odometry (robot_id, sim_time_ms, left_m, right_m) VALUES (1, 0, 0, 0)", "DELETE FROM odometry",
                "SELECT * FROM engine_state", "SELECT * FROM sensor_requests", "DROP TABLE engine_comments",
                "CREATE TABLE intruder (id INT)", "GRANT SELECT ON strategy TO '" + deployment.robotUser + "'@'%'")) {
            assertThatThrownBy(() -> asViewer(sql)).as("viewer: " + sql).isInstanceOf(SQLException.class);
        }
    }

    private void asViewer(String sql) throws SQLException {
        deployment.executeAs(deployment.viewerUser, Deployment.VIEWER_PASSWORD, sql);
    }

    @Test
    void theDbUsersCommandGrantsExactlyWhatTheComposeInitGrants() throws Exception {
        List<String> engineGrants = grants(deployment.engineUser);
        List<String> robotGrants = grants(deployment.robotUser);
        List<String> viewerGrants = grants(deployment.viewerUser);
        assertThat(viewerGrants).hasSize(14); // USAGE and thirteen SELECTs (initial_pose and pose_estimate among them)
        assertThat(engineGrants).hasSizeGreaterThan(10);
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(new StringWriter(), true));
        cl.setErr(new PrintWriter(err, true));
        for (int i = 0; i < 2; i++) { // idempotent
            int code = cl.execute("db", "users", "--db", deployment.adminUrl(), "--engine-user", deployment.engineUser,
                    "--robot-user", deployment.robotUser, "--engine-password", Deployment.ENGINE_PASSWORD,
                    "--robot-password", Deployment.ROBOT_PASSWORD, "--viewer-user", deployment.viewerUser,
                    "--viewer-password", Deployment.VIEWER_PASSWORD);
            assertThat(code).as(err.toString()).isZero();
        }
        assertThat(grants(deployment.viewerUser)).containsExactlyInAnyOrderElementsOf(viewerGrants);
        assertThat(grants(deployment.engineUser)).containsExactlyInAnyOrderElementsOf(engineGrants);
        assertThat(grants(deployment.robotUser)).containsExactlyInAnyOrderElementsOf(robotGrants);
        asRobot("SELECT COUNT(*) FROM engine_clock"); // the password still works
    }

    @Test
    void dbUsersRefusesAPasswordThatWouldBreakTheScript() {
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setErr(new PrintWriter(err, true));
        int code = cl.execute("db", "users", "--db", deployment.adminUrl(), "--engine-password", "it's", "--robot-password", "x");
        assertThat(code).isEqualTo(2);
        assertThat(err.toString()).contains("must not contain");
    }

    private static List<String> grants(String user) throws SQLException {
        List<String> out = new ArrayList<>();
        try (Connection c = DriverManager.getConnection(deployment.adminUrl()); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SHOW GRANTS FOR '" + user + "'@'%'")) {
            while (rs.next()) {
                out.add(rs.getString(1).replaceAll("IDENTIFIED BY PASSWORD '[^']*'", ""));
            }
        }
        return out;
    }
}
