package org.proactiverobotics.robot;

import static org.assertj.core.api.Assertions.assertThat;

import com.zaxxer.hikari.HikariDataSource;
import java.net.ServerSocket;
import java.util.List;
import java.util.UUID;
import org.h2.tools.Server;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.robot.link.RobotPool;
import org.proactiverobotics.sim2d.Simulation;

/**
 * A real outage: the robot reaches its database through an H2 TCP server that is stopped and
 * started again (a shared MariaDB server cannot be stopped from a test). The engine's side
 * writes through an embedded connection to the same in-memory database, so it keeps sending
 * commands the robot cannot see.
 */
class DatabaseOutageTest {

    private static final int ROBOT = 3;

    @Test
    void withTheDatabaseStoppedTheRobotStopsAtOnceAndItRecoversWhenTheDatabaseReturns() throws Exception {
        String name = "outage_" + UUID.randomUUID().toString().replace("-", "").substring(0, 8);
        int port;
        try (ServerSocket probe = new ServerSocket(0)) {
            port = probe.getLocalPort();
        }
        Server server = Server.createTcpServer("-tcpPort", String.valueOf(port), "-ifNotExists").start();
        String tcpUrl = "jdbc:h2:tcp://localhost:" + port + "/mem:" + name + Databases.H2_MYSQL_MODE;
        RobotConfig config = RobotConfig.defaults(ROBOT).withWatchdogTimeoutMs(320).withRealTimeFactor(0)
                .withRetention(RetentionPolicy.KEEP_ALL).withBackoff(20, 100);
        Simulation sim = new Simulation(TestWorlds.arena().withObstacles(List.of()));
        try (HikariDataSource enginePool = Databases.pool(Databases.embeddedH2Url(name), "sa", "");
             HikariDataSource robotPool = RobotPool.open(tcpUrl, "sa", "", 1_000);
             ProactiveController robot = new ProactiveController(sim, new JdbcRobotLink(robotPool), config)) {
            Schema.apply(enginePool);
            FakeEngine engine = new FakeEngine(enginePool, ROBOT);

            for (int i = 0; i < 5; i++) { // the engine sends a command every iteration
                engine.command("FORWARD 0.2");
                robot.controlStep();
                sim.step();
            }
            assertThat(robot.mode()).isEqualTo(Mode.FORWARD);
            assertThat(robot.databaseFailing()).isFalse();

            server.stop();
            engine.request("GPS");
            double atFailure = sim.groundTruth().distanceM();
            long startNanos = System.nanoTime();
            int steps = 0;
            while (!robot.stoppedUntilNewCommand() && steps < 40) {
                engine.command("FORWARD 0.2"); // sent, but the robot cannot read it
                robot.controlStep();
                sim.step();
                steps++;
            }
            long wallMs = (System.nanoTime() - startNanos) / 1_000_000;
            assertThat(robot.stoppedUntilNewCommand()).isTrue();
            // Stopped at the step the link failed, not 320 ms of blind driving later when the watchdog would expire.
            assertThat(steps).isEqualTo(1);
            assertThat(sim.groundTruth().distanceM()).isEqualTo(atFailure);
            assertThat(robot.stats().linkStops()).isEqualTo(1);
            assertThat(robot.stats().watchdogStops()).isZero();
            assertThat(wallMs).as("the loop never blocks for long").isLessThan(2_500);
            assertThat(robot.databaseFailing()).isTrue();
            assertThat(sim.robot().leftSpeedMps()).isZero();
            double stoppedAt = sim.groundTruth().distanceM();
            // Stay down a while: the loop keeps stepping, retrying with back-off, never blocking long.
            long downUntil = System.nanoTime() + 800_000_000L;
            long longestStepMs = 0;
            while (System.nanoTime() < downUntil) {
                long t0 = System.nanoTime();
                robot.controlStep();
                sim.step();
                longestStepMs = Math.max(longestStepMs, (System.nanoTime() - t0) / 1_000_000);
            }
            assertThat(longestStepMs).as("longest step while down, ms").isLessThan(2_500); // one connection time-out + slack
            assertThat(sim.groundTruth().distanceM()).isEqualTo(stoppedAt);
            RobotStats during = robot.stats();
            assertThat(during.outages()).isEqualTo(1);
            assertThat(during.failedCalls()).isGreaterThanOrEqualTo(2);
            assertThat(during.skippedCalls()).isPositive();
            assertThat(engine.pending()).isEqualTo(1);

            server = Server.createTcpServer("-tcpPort", String.valueOf(port), "-ifNotExists").start();
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (robot.stoppedUntilNewCommand() && System.nanoTime() < deadline) {
                engine.command("FORWARD 0.2");
                robot.controlStep();
                sim.step();
            }
            assertThat(robot.stoppedUntilNewCommand()).isFalse();
            assertThat(robot.databaseFailing()).isFalse();
            assertThat(robot.mode()).isEqualTo(Mode.FORWARD);
            robot.controlStep();
            assertThat(engine.pending()).isZero(); // the request made during the outage is answered now
            sim.step();
            assertThat(sim.groundTruth().distanceM()).isGreaterThan(stoppedAt);
            assertThat(robot.stats().outages()).isEqualTo(1);
        } finally {
            server.stop();
        }
    }
}
