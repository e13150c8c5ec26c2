-- proactive-robotics: the two least-privilege database users of the two-process deployment.
--
-- A template. @DATABASE@, @HOST@, @ENGINE_USER@, @ENGINE_PASSWORD@, @ROBOT_USER@,
-- @ROBOT_PASSWORD@, @VIEWER_USER@ and @VIEWER_PASSWORD@ are filled in by deploy/mysql-init/02-users.sh (docker compose's MySQL
-- initialisation) or by `proactive db users` (an existing server). Apply it as an
-- administrator after schema.sql (MySQL grants on a table only once it exists). Idempotent:
-- applying it again resets the passwords and adds no privilege.
--
-- Neither user may CREATE, DROP, ALTER or GRANT anything; each writes only its own tables.
-- The viewer (`watch`) is optional: without a viewer password, every line naming it is left out.
-- MariaDB 10.6+ and MySQL 8 accept every statement unchanged.

CREATE USER IF NOT EXISTS '@ENGINE_USER@'@'@HOST@' IDENTIFIED BY '@ENGINE_PASSWORD@';
ALTER USER '@ENGINE_USER@'@'@HOST@' IDENTIFIED BY '@ENGINE_PASSWORD@';
CREATE USER IF NOT EXISTS '@ROBOT_USER@'@'@HOST@' IDENTIFIED BY '@ROBOT_PASSWORD@';
ALTER USER '@ROBOT_USER@'@'@HOST@' IDENTIFIED BY '@ROBOT_PASSWORD@';

-- ---- The engine: reads the robot tables, writes its own --------------------------------
GRANT SELECT ON `@DATABASE@`.gps_stored_values TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.iudata TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.distance_sensor_data TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.battery_level TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.odometry TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.battery_recharged TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.recharge_station TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.initial_pose TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.robot_body TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.robot_clock TO '@ENGINE_USER@'@'@HOST@';
-- it marks checkpoints reached or unreachable (and neither when a new robot run starts)
GRANT SELECT, UPDATE (reached, reached_sim_time_ms, unreachable) ON `@DATABASE@`.checkpoints TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.engine_comments TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.sensor_requests TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.strategy TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.engine_state TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.engine_queue TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.rule_failures TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.engine_clock TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE, DELETE ON `@DATABASE@`.occupancy_map TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, DELETE ON `@DATABASE@`.pose_estimate TO '@ENGINE_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE ON `@DATABASE@`.engine_lease TO '@ENGINE_USER@'@'@HOST@';

-- ---- The robot: writes its readings, answers requests, reads commands ----------------------
-- DELETE on its readings: the retention policy, and a new run starting clean
GRANT SELECT, INSERT, DELETE ON `@DATABASE@`.gps_stored_values TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT, DELETE ON `@DATABASE@`.iudata TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT, DELETE ON `@DATABASE@`.distance_sensor_data TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT, DELETE ON `@DATABASE@`.battery_level TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT, DELETE ON `@DATABASE@`.odometry TO '@ROBOT_USER@'@'@HOST@';
-- it marks requests answered, and prunes answered ones
GRANT SELECT, UPDATE (answered_sim_time_ms) ON `@DATABASE@`.sensor_requests TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.engine_comments TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.engine_clock TO '@ROBOT_USER@'@'@HOST@';
-- the mission rows, seeded from the world file once per robot id
GRANT SELECT, INSERT ON `@DATABASE@`.checkpoints TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT ON `@DATABASE@`.recharge_station TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT ON `@DATABASE@`.initial_pose TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT ON `@DATABASE@`.battery_recharged TO '@ROBOT_USER@'@'@HOST@';
-- its body (speed, size), written at the start of every run
GRANT SELECT, INSERT, UPDATE ON `@DATABASE@`.robot_body TO '@ROBOT_USER@'@'@HOST@';
GRANT SELECT, INSERT, UPDATE ON `@DATABASE@`.robot_clock TO '@ROBOT_USER@'@'@HOST@';

-- ---- The viewer (`watch`): reads what the live view shows, writes nothing ------------------
CREATE USER IF NOT EXISTS '@VIEWER_USER@'@'@HOST@' IDENTIFIED BY '@VIEWER_PASSWORD@';
ALTER USER '@VIEWER_USER@'@'@HOST@' IDENTIFIED BY '@VIEWER_PASSWORD@';
GRANT SELECT ON `@DATABASE@`.engine_comments TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.gps_stored_values TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.iudata TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.distance_sensor_data TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.battery_level TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.odometry TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.checkpoints TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.recharge_station TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.initial_pose TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.rule_failures TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.strategy TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.occupancy_map TO '@VIEWER_USER@'@'@HOST@';
GRANT SELECT ON `@DATABASE@`.pose_estimate TO '@VIEWER_USER@'@'@HOST@';
