package org.proactiverobotics.bench.robot;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.robot.RobotConfig;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.robot.link.RobotPool;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Time of one control step of the robot side: answer three pending sensor requests (GPS, IU,
 * DS: one GPS row, one IU row, a batch of distance rows (one per ray), three "answered" marks, in one
 * transaction) and read the newest command, on embedded H2 and on MariaDB over loopback.
 * Before each step (not timed) the simulation advances one step and a stand-in engine writes
 * the three requests and a new command through its own pool. The default retention policy is
 * on, so its pruning (every 100 steps) is part of the average.
 *
 * <pre>
 * java -jar bench/target/benchmarks.jar RobotStepBenchmark
 * PROACTIVE_BENCH_MARIADB_URL='jdbc:mariadb://127.0.0.1:3306/?user=root&amp;password=' java -jar bench/target/benchmarks.jar RobotStepBenchmark
 * </pre>
 * The MariaDB case needs that variable (or PROACTIVE_TEST_MARIADB_URL): a server URL whose user
 * may create a database; it creates and drops {@code proactive_bench_<random>}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class RobotStepBenchmark {

    private static final int ROBOT = 1;

    /** Which database: H2 (embedded, in memory, MySQL mode) or MARIADB (over loopback). */
    @Param({"H2", "MARIADB"})
    public String database;

    private HikariDataSource robotPool;
    private HikariDataSource enginePool;
    private Simulation sim;
    private ProactiveController robot;
    private Runnable drop = () -> { };
    private long iteration;

    /** Opens the database, applies the schema, starts the robot. */
    @Setup(Level.Trial)
    public void setUp() throws SQLException {
        quietLogs();
        String unique = "proactive_bench_" + UUID.randomUUID().toString().replace("-", "").substring(0, 8);
        String url;
        if ("H2".equals(database)) {
            url = Databases.embeddedH2Url(unique);
        } else {
            String server = System.getenv("PROACTIVE_BENCH_MARIADB_URL");
            if (server == null || server.isBlank()) {
                server = System.getenv("PROACTIVE_TEST_MARIADB_URL");
            }
            if (server == null || server.isBlank()) {
                throw new IllegalStateException("set PROACTIVE_BENCH_MARIADB_URL (e.g. "
                        + "jdbc:mariadb://127.0.0.1:3306/?user=root&password=) to benchmark MariaDB");
            }
            String base = server;
            try (Connection c = DriverManager.getConnection(base); Statement s = c.createStatement()) {
                s.execute("CREATE DATABASE " + unique);
            }
            url = base.replaceFirst("(jdbc:(?:mariadb|mysql)://[^/?]+)/?[^?]*", "$1/" + unique);
            drop = () -> {
                try (Connection c = DriverManager.getConnection(base); Statement s = c.createStatement()) {
                    s.execute("DROP DATABASE IF EXISTS " + unique);
                } catch (SQLException e) {
                    throw new IllegalStateException(e);
                }
            };
        }
        String user = "H2".equals(database) ? "sa" : null;
        String password = "H2".equals(database) ? "" : null;
        robotPool = RobotPool.open(url, user, password);
        enginePool = Databases.multiStatementPool(url, user, password);
        Schema.apply(enginePool);
        WorldSpec world = new WorldSpec("bench-arena", 32, 1e9, 1, new WorldSpec.Arena(5.0),
                new WorldSpec.Robot(0.0, -4.0, 90.0, 0.12, 0.5, 1.0),
                List.of(WorldSpec.Obstacle.circle(0.0, -3.2, 0.2)),
                List.of(new WorldSpec.Checkpoint(0.0, 3.0)), 0.25,
                new WorldSpec.RechargeStation(-3.0, 0.0, 0.35), WorldSpec.Battery.DEFAULT);
        sim = new Simulation(world);
        RobotConfig config = RobotConfig.defaults(ROBOT).withRealTimeFactor(0).withRetention(RetentionPolicy.DEFAULT);
        robot = new ProactiveController(sim, new JdbcRobotLink(robotPool), config);
        robot.controlStep(); // seeds the mission, writes the start battery level
    }

    /** Logback's default is DEBUG on the console, which would time the logging of every statement. */
    private static void quietLogs() {
        if (org.slf4j.LoggerFactory.getLogger(org.slf4j.Logger.ROOT_LOGGER_NAME)
                instanceof ch.qos.logback.classic.Logger root) {
            root.setLevel(ch.qos.logback.classic.Level.WARN);
        }
    }

    /** Not timed: the world moves on; the engine asks for GPS, IU and DS and sends a command. */
    @Setup(Level.Invocation)
    public void engineIteration() throws SQLException {
        sim.step();
        iteration++;
        try (Connection c = enginePool.getConnection();
             PreparedStatement request = c.prepareStatement(
                     "INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (?, ?, ?)");
             PreparedStatement command = c.prepareStatement("INSERT INTO engine_comments "
                     + "(robot_id, iteration, sim_time_ms, scenario, command) VALUES (?, ?, ?, 'Bench', ?)")) {
            for (String sensor : new String[] {"GPS", "IU", "DS"}) {
                request.setInt(1, ROBOT);
                request.setString(2, sensor);
                request.setLong(3, iteration);
                request.addBatch();
            }
            request.executeBatch();
            command.setInt(1, ROBOT);
            command.setLong(2, iteration);
            command.setLong(3, sim.simTimeMs());
            command.setString(4, (iteration & 1) == 0 ? "TURN_LEFT 0.1" : "TURN_RIGHT 0.1");
            command.executeUpdate();
        }
    }

    /**
     * One control step: answer the three requests, read and execute the newest command.
     *
     * @return the robot's stats, so that nothing is optimised away
     */
    @Benchmark
    public Object controlStep() {
        robot.controlStep();
        return robot.mode();
    }

    /** Checks that every request was answered, then closes everything. */
    @TearDown(Level.Trial)
    public void tearDown() {
        var stats = robot.stats();
        robot.close();
        enginePool.close();
        robotPool.close();
        drop.run();
        if (stats.failedCalls() > 0 || stats.readingsNotWritten() > 0) {
            throw new IllegalStateException("database failures during the benchmark: " + stats);
        }
        System.out.println("\nrobot stats: " + stats);
    }
}
