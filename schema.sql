-- proactive-robotics: the one schema.
-- Applies unchanged to H2 (MODE=MySQL;DATABASE_TO_LOWER=TRUE) and to MySQL 8 / MariaDB 10.6+.
-- Re-applying it is harmless (IF NOT EXISTS everywhere).
--
-- Conventions: every table has robot_id, so several robots can share one database; readings
-- carry the simulated time in milliseconds (sim_time_ms); column names carry units:
-- _m metres, _rad radians, _pct percent (0-100), _ms milliseconds.
-- The robot writes readings; the engine writes requests, commands and its own state.
-- "Newest" is by simulated time (readings) or by the engine's iteration (commands), never by id:
-- on a Galera cluster ids from different nodes interleave. The reads go through
-- (robot_id, sim_time_ms, id) and (robot_id, iteration, id) indexes, written as
-- ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1: H2 walks an index backwards only
-- when the ORDER BY names its columns (a plain ORDER BY id DESC scans every row of the robot).
-- A database made before these indexes gets them from the application (db.Schema), which drops
-- the (robot_id, id) indexes they replace.

-- ======================================================================================
-- The paper's eight tables
-- ======================================================================================

-- GPS readings, written by the robot when the engine asks (sensor_requests.sensor = 'GPS').
CREATE TABLE IF NOT EXISTS gps_stored_values (
  id          BIGINT AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT    NOT NULL,
  sim_time_ms BIGINT NOT NULL,
  x_m         DOUBLE NOT NULL,
  y_m         DOUBLE NOT NULL,
  INDEX idx_gps_time (robot_id, sim_time_ms, id)
);

-- Inertial unit readings (sensor 'IU'); yaw 0 = +x axis, counter-clockwise positive.
CREATE TABLE IF NOT EXISTS iudata (
  id          BIGINT AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT    NOT NULL,
  sim_time_ms BIGINT NOT NULL,
  roll_rad    DOUBLE NOT NULL,
  pitch_rad   DOUBLE NOT NULL,
  yaw_rad     DOUBLE NOT NULL,
  INDEX idx_iu_time (robot_id, sim_time_ms, id)
);

-- Distance sensor readings (sensor 'DS'): one row per sensor; one reading = the rows of one
-- robot sharing a sim_time_ms. angle_rad is the sensor's direction relative to the robot's
-- heading; distance_m equals range_m when the ray hits nothing. The newest reading and its rows
-- are both found through (robot_id, sim_time_ms): one index less to keep up on 21 rows a step.
CREATE TABLE IF NOT EXISTS distance_sensor_data (
  id           BIGINT AUTO_INCREMENT PRIMARY KEY,
  robot_id     INT    NOT NULL,
  sim_time_ms  BIGINT NOT NULL,
  sensor_index INT    NOT NULL,
  angle_rad    DOUBLE NOT NULL,
  distance_m   DOUBLE NOT NULL,
  range_m      DOUBLE NOT NULL,
  INDEX idx_ds_time (robot_id, sim_time_ms)
);

-- Battery readings (sensor 'BATTERY'); the robot writes one at start with the full level.
CREATE TABLE IF NOT EXISTS battery_level (
  id          BIGINT  AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT     NOT NULL,
  sim_time_ms BIGINT  NOT NULL,
  level_pct   DOUBLE  NOT NULL,
  charging    BOOLEAN NOT NULL DEFAULT FALSE,
  INDEX idx_battery_time (robot_id, sim_time_ms, id)
);

-- The level a recharge stops at (mission row, seeded from the world file).
CREATE TABLE IF NOT EXISTS battery_recharged (
  robot_id  INT    NOT NULL PRIMARY KEY,
  level_pct DOUBLE NOT NULL
);

-- The checkpoints to reach, in seq order (mission rows, seeded from the world file).
-- The engine marks them reached, or unreachable when no route leads there (the mission ends).
CREATE TABLE IF NOT EXISTS checkpoints (
  robot_id            INT     NOT NULL,
  seq                 INT     NOT NULL,
  x_m                 DOUBLE  NOT NULL,
  y_m                 DOUBLE  NOT NULL,
  radius_m            DOUBLE  NOT NULL,
  reached             BOOLEAN NOT NULL DEFAULT FALSE,
  reached_sim_time_ms BIGINT,
  unreachable         BOOLEAN NOT NULL DEFAULT FALSE,
  PRIMARY KEY (robot_id, seq)
);

-- The commands the engine sends; the robot executes the newest one.
-- command is text: a Mode name and its arguments, e.g. "STOP", "DRIVE 0.40 0.35"
-- (left and right wheel speeds in m/s), "RECHARGE". sim_time_ms is the simulated time of
-- the newest reading the engine based it on; scenario is the one whose suggestion won.
CREATE TABLE IF NOT EXISTS engine_comments (
  id          BIGINT       AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT          NOT NULL,
  iteration   BIGINT       NOT NULL,
  sim_time_ms BIGINT       NOT NULL,
  scenario    VARCHAR(64)  NOT NULL,
  command     VARCHAR(255) NOT NULL,
  created_at  TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3),
  INDEX idx_comments_iteration (robot_id, iteration, id)
);

-- Where the robot recharges (mission row, seeded from the world file).
CREATE TABLE IF NOT EXISTS recharge_station (
  robot_id INT    NOT NULL PRIMARY KEY,
  x_m      DOUBLE NOT NULL,
  y_m      DOUBLE NOT NULL,
  radius_m DOUBLE NOT NULL
);

-- Where the robot stands when the mission starts (mission row, seeded from the world file): the
-- initial pose an operator gives a localiser, the one place a robot without GPS learns where it
-- is in the mission's frame. Metres; heading in radians, counter-clockwise from +x.
CREATE TABLE IF NOT EXISTS initial_pose (
  robot_id INT    NOT NULL PRIMARY KEY,
  x_m      DOUBLE NOT NULL,
  y_m      DOUBLE NOT NULL,
  yaw_rad  DOUBLE NOT NULL
);

-- The robot's body as its engine must assume it (written by the robot process at the start of
-- every run, from the world file's robot): its top wheel speed, metres per second, and the
-- distance between its wheels (twice its radius), metres. An engine serving robots of different
-- sizes drives each with its own; without a row it takes its --max-speed-mps / --axle-width-m.
-- shared_world: other robots share the robot's world (a world file with `robots`), so its engine
-- runs the traffic scenario, Yield, as `run` does.
CREATE TABLE IF NOT EXISTS robot_body (
  robot_id      INT     NOT NULL PRIMARY KEY,
  max_speed_mps DOUBLE  NOT NULL,
  axle_width_m  DOUBLE  NOT NULL,
  shared_world  BOOLEAN NOT NULL DEFAULT FALSE
);

-- ======================================================================================
-- Sensors beyond the paper's
-- ======================================================================================

-- Wheel odometry (sensor 'ODOMETRY'): how far each wheel rolled since the robot's previous
-- odometry reading, metres, positive forwards (turning on the spot: opposite signs). Summing a
-- robot's rows in sim_time_ms order gives each wheel's whole travel (until pruning drops the
-- oldest). The wheels' own count: a wheel spinning against a wall still rolls.
CREATE TABLE IF NOT EXISTS odometry (
  id          BIGINT AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT    NOT NULL,
  sim_time_ms BIGINT NOT NULL,
  left_m      DOUBLE NOT NULL,
  right_m     DOUBLE NOT NULL,
  INDEX idx_odometry_time (robot_id, sim_time_ms, id)
);

-- ======================================================================================
-- The engine's own tables
-- ======================================================================================

-- Requests for fresh sensor data (Data acquisition scenario). sensor is one of
-- 'GPS', 'IU', 'DS', 'BATTERY', 'ODOMETRY'. Pending while answered_sim_time_ms is NULL; the robot
-- answers by writing a reading and setting answered_sim_time_ms.
CREATE TABLE IF NOT EXISTS sensor_requests (
  id                    BIGINT      AUTO_INCREMENT PRIMARY KEY,
  robot_id              INT         NOT NULL,
  sensor                VARCHAR(16) NOT NULL,
  iteration             BIGINT      NOT NULL,
  answered_sim_time_ms  BIGINT,
  INDEX idx_requests_pending (robot_id, answered_sim_time_ms)
);

-- The strategy: the PriorityArray. One row per CommandArray slot; the highest priority is
-- read first. Changing a row while the engine runs changes the next iteration's decision.
-- timeout_ms: how long a slot's suggestion is obeyed after it was entered, in simulated ms
-- (twist_mux style); 0 = only in the iteration it was entered.
CREATE TABLE IF NOT EXISTS strategy (
  robot_id      INT          NOT NULL,
  slot          INT          NOT NULL,
  scenario      VARCHAR(64)  NOT NULL,
  priority      INT          NOT NULL,
  strategy_name VARCHAR(64)  NOT NULL,
  timeout_ms    BIGINT       NOT NULL DEFAULT 0,
  updated_at    TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3),
  PRIMARY KEY (robot_id, slot)
);

-- The engine's saved state (the paper's failsafe), written in one transaction at the end of
-- every iteration: the iteration number and the memory scenarios share (JSON) ...
CREATE TABLE IF NOT EXISTS engine_state (
  robot_id    INT          NOT NULL PRIMARY KEY,
  iteration   BIGINT       NOT NULL,
  memory_json LONGTEXT     NOT NULL,
  saved_at    TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3)
);

-- ... and nextQueue, rule by rule in queue order (rule type + fields as JSON, with Gson).
CREATE TABLE IF NOT EXISTS engine_queue (
  robot_id  INT          NOT NULL,
  position  INT          NOT NULL,
  rule_type VARCHAR(255) NOT NULL,
  rule_json LONGTEXT     NOT NULL,
  PRIMARY KEY (robot_id, position)
);

-- The robot's occupancy map (the Mapping scenario), built from its distance scans and GPS/IU
-- readings: squares of 16 x 16 cells of 0.05 m; chunk (cx, cy) covers x from cx * 0.8 m and y
-- from cy * 0.8 m. cells: 256 bytes, row by row from the lower-left cell, 0 unknown, 1 free,
-- 2 occupied. Only chunks that changed are rewritten.
CREATE TABLE IF NOT EXISTS occupancy_map (
  robot_id            INT            NOT NULL,
  chunk_x             INT            NOT NULL,
  chunk_y             INT            NOT NULL,
  cells               VARBINARY(256) NOT NULL,
  updated_sim_time_ms BIGINT         NOT NULL,
  PRIMARY KEY (robot_id, chunk_x, chunk_y)
);

-- The engine's pose estimate (the Localisation scenario): one row per iteration, the robot's
-- position (metres) and heading (radians) as odometry, the inertial unit, the GPS (when there is
-- one) and the scan matched against the occupancy map put it, with the estimate's covariance
-- (square metres, metre-radians, square radians). Every scenario that needs the robot's pose reads
-- the newest row, never the raw GPS. The engine keeps its newest rows (pruned like its commands).
CREATE TABLE IF NOT EXISTS pose_estimate (
  id          BIGINT AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT    NOT NULL,
  sim_time_ms BIGINT NOT NULL,
  x_m         DOUBLE NOT NULL,
  y_m         DOUBLE NOT NULL,
  yaw_rad     DOUBLE NOT NULL,
  var_x       DOUBLE NOT NULL,
  var_y       DOUBLE NOT NULL,
  var_yaw     DOUBLE NOT NULL,
  cov_xy      DOUBLE NOT NULL,
  cov_x_yaw   DOUBLE NOT NULL,
  cov_y_yaw   DOUBLE NOT NULL,
  INDEX idx_pose_estimate_time (robot_id, sim_time_ms, id)
);

-- Every failure of a rule part: which rule, of which scenario, which part, and why.
CREATE TABLE IF NOT EXISTS rule_failures (
  id         BIGINT        AUTO_INCREMENT PRIMARY KEY,
  robot_id   INT           NOT NULL,
  iteration  BIGINT        NOT NULL,
  rule       VARCHAR(255)  NOT NULL,
  scenario   VARCHAR(64)   NOT NULL,
  part       VARCHAR(32)   NOT NULL,
  message    VARCHAR(1000) NOT NULL,
  created_at TIMESTAMP(3)  NOT NULL DEFAULT CURRENT_TIMESTAMP(3),
  INDEX idx_failures_iteration (robot_id, iteration)
);

-- ======================================================================================
-- The lockstep handshake of the two processes (the `robot` and `engine` commands)
-- ======================================================================================
-- Two tables, one per writer, so that each side's database user writes only its own.

-- The robot's clock, written only by the robot. One robot process is one run (run_id); step is
-- the control step whose sensing is done (0 = the run has started, nothing sensed yet);
-- timing is 'sync' (the robot waits for engine_clock before acting) or 'realtime';
-- state is 'RUNNING', 'FINISHED' or 'STOPPED'.
CREATE TABLE IF NOT EXISTS robot_clock (
  robot_id    INT          NOT NULL PRIMARY KEY,
  run_id      BIGINT       NOT NULL,
  step        BIGINT       NOT NULL,
  sim_time_ms BIGINT       NOT NULL,
  timing      VARCHAR(16)  NOT NULL,
  state       VARCHAR(16)  NOT NULL,
  updated_at  TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3)
);

-- The engine's clock, written only by the engine: the robot run it serves, the last robot step
-- it ran an iteration for (0 = run acknowledged, its engine rows reset), and that iteration.
CREATE TABLE IF NOT EXISTS engine_clock (
  robot_id   INT          NOT NULL PRIMARY KEY,
  run_id     BIGINT       NOT NULL,
  step       BIGINT       NOT NULL,
  iteration  BIGINT       NOT NULL,
  updated_at TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3)
);

-- Which engine process serves a robot, when several engines share a fleet (`engine --robot-ids`).
-- An engine takes the row when it is free or expired (taking it bumps epoch) and renews it in
-- every iteration's own transaction, checking owner and epoch: an engine that lost the row
-- commits nothing more for that robot, so two engines never both drive it. Times are the
-- database server's (one clock for every engine, on every machine).
CREATE TABLE IF NOT EXISTS engine_lease (
  robot_id   INT          NOT NULL PRIMARY KEY,
  owner      VARCHAR(128) NOT NULL,
  epoch      BIGINT       NOT NULL,
  iteration  BIGINT       NOT NULL DEFAULT 0,
  expires_at TIMESTAMP(3) NOT NULL,
  taken_at   TIMESTAMP(3) NOT NULL DEFAULT CURRENT_TIMESTAMP(3)
);
