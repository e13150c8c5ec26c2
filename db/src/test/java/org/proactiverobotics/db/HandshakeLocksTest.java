package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;

import com.zaxxer.hikari.HikariDataSource;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.HandshakeLocks.Wake;

/**
 * The handshake's wake-ups on a real MariaDB: a side blocks in the server until the other gives
 * its signal, the three locks stay in phase over many steps, and a side that goes away (its
 * session ends, or its locks are released) never leaves the other waiting.
 */
class HandshakeLocksTest {

    private static final long LONG_NANOS = TimeUnit.SECONDS.toNanos(10);
    private static final String QUERY = "SELECT ? AS robot";

    private static HikariDataSource pool(TestDatabase db) {
        HikariDataSource pool = new HikariDataSource(Databases.allowMultiStatements(
                Databases.config(db.jdbcUrl(), db.user(), db.password()), db.jdbcUrl()));
        pool.setMaximumPoolSize(4);
        return pool;
    }

    /** One exchange; returns what the query read (the robot id), so that the query is seen to run after the wait. */
    private static int exchange(HandshakeLocks locks, long given, long awaited, long timeoutNanos) throws Exception {
        return locks.exchange(given, awaited, timeoutNanos, QUERY, (ps, p) -> ps.setInt(p, 7), rs -> {
            rs.next();
            return rs.getInt(1);
        });
    }

    @Test
    void h2CannotWaitOnLocks() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2); HikariDataSource pool = pool(db)) {
            assertThat(new HandshakeLocks(pool, 1).usable()).isFalse();
        }
    }

    @Test
    void aWaitEndsWhenTheOtherSideGivesItsSignalAndNotBefore() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB); HikariDataSource pool = pool(db);
             HandshakeLocks engine = new HandshakeLocks(pool, 1); HandshakeLocks robot = new HandshakeLocks(pool, 1)) {
            assertThat(engine.usable()).isTrue();
            // the engine woke on the robot's "sensed step 1" and so holds the lock of "served step 2" (signal 5)
            exchange(engine, -1, HandshakeLocks.sensed(1), LONG_NANOS);
            assertThat(engine.lastWake()).isEqualTo(Wake.ACQUIRED);
            CompletableFuture<Integer> waiting = CompletableFuture.supplyAsync(() -> {
                try {
                    return exchange(robot, HandshakeLocks.sensed(2), HandshakeLocks.served(2), LONG_NANOS);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            Thread.sleep(300);
            assertThat(waiting).as("the robot waits in the server while the engine iterates").isNotDone();

            exchange(engine, HandshakeLocks.served(2), HandshakeLocks.sensed(3), LONG_NANOS); // "served step 2"
            assertThat(waiting.get(5, TimeUnit.SECONDS)).as("the query ran after the wait").isEqualTo(7);
            assertThat(robot.lastWake()).isEqualTo(Wake.ACQUIRED);
        }
    }

    @Test
    void aWaitTimesOutWhileTheOtherSideHoldsTheLockAndTheQueryStillRuns() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB); HikariDataSource pool = pool(db);
             HandshakeLocks engine = new HandshakeLocks(pool, 1); HandshakeLocks robot = new HandshakeLocks(pool, 1)) {
            exchange(engine, -1, HandshakeLocks.sensed(1), LONG_NANOS);
            assertThat(exchange(robot, -1, HandshakeLocks.served(2), TimeUnit.MILLISECONDS.toNanos(50))).isEqualTo(7);
            assertThat(robot.lastWake()).isEqualTo(Wake.TIMED_OUT);
            assertThat(robot.count(Wake.TIMED_OUT)).isEqualTo(1);
            // the other robot's locks are its own: robot 2 waits for nothing robot 1's engine holds
            try (HandshakeLocks other = new HandshakeLocks(pool, 2)) {
                exchange(other, -1, HandshakeLocks.served(2), TimeUnit.MILLISECONDS.toNanos(50));
                assertThat(other.lastWake()).isEqualTo(Wake.ACQUIRED);
            }
        }
    }

    @Test
    void aSideThatGoesAwayReleasesEverythingAndItsPooledConnectionKeepsNoLock() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB); HikariDataSource pool = pool(db);
             HandshakeLocks robot = new HandshakeLocks(pool, 1)) {
            HandshakeLocks engine = new HandshakeLocks(pool, 1);
            exchange(engine, -1, HandshakeLocks.sensed(1), LONG_NANOS);
            assertThat(engine.holdsAny()).isTrue();
            CompletableFuture<Integer> waiting = CompletableFuture.supplyAsync(() -> {
                try {
                    return exchange(robot, -1, HandshakeLocks.served(2), LONG_NANOS);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            Thread.sleep(200);
            assertThat(waiting).isNotDone();
            // the engine stops serving the robot: its connection goes back to the pool, open, without the lock
            engine.close();
            assertThat(waiting.get(5, TimeUnit.SECONDS)).isEqualTo(7);
            assertThat(engine.holdsAny()).isFalse();
        }
    }

    @Test
    void aSideWhosePeerDoesNotUseTheLocksStopsWaitingInTheServerForAWhile() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB); HikariDataSource pool = pool(db);
             HandshakeLocks robot = new HandshakeLocks(pool, 1)) {
            // an engine thread of several robots polls: every lock is free, every wake-up finds nothing
            for (long k = 1; k <= 3; k++) {
                exchange(robot, HandshakeLocks.sensed(k), HandshakeLocks.served(k), LONG_NANOS);
                assertThat(robot.lastWake()).isEqualTo(Wake.ACQUIRED);
                robot.found(false);
                assertThat(robot.paused()).as("the rotation's first steps miss by design").isFalse();
            }
            exchange(robot, HandshakeLocks.sensed(4), HandshakeLocks.served(4), LONG_NANOS);
            robot.found(false);
            assertThat(robot.paused()).isTrue();
            assertThat(robot.holdsAny()).as("no lock kept while not using them").isFalse();
        }
    }

    @Test
    void locksHeldByASessionThatIsNotTheOtherSideMakeASideStopWaitingInTheServer() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB); HikariDataSource pool = pool(db);
             HandshakeLocks stale = new HandshakeLocks(pool, 1); HandshakeLocks robot = new HandshakeLocks(pool, 1)) {
            for (long signal = 0; signal < 3; signal++) { // an engine that hung, its session still open, holds all three
                exchange(stale, -1, signal, LONG_NANOS);
            }
            for (long k = 1; k <= 4; k++) { // a new engine serves each step (by polling); every wait times out
                exchange(robot, HandshakeLocks.sensed(k), HandshakeLocks.served(k), TimeUnit.MILLISECONDS.toNanos(30));
                assertThat(robot.lastWake()).isEqualTo(Wake.TIMED_OUT);
                robot.found(true);
            }
            assertThat(robot.paused()).as("no 200 ms stall per step for as long as the stale session lives").isTrue();
        }
    }

    @Test
    void aCycleOfWaitsWithAnotherSessionEndsTheWaitAndStillReads() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB); HikariDataSource pool = pool(db);
             HandshakeLocks stale = new HandshakeLocks(pool, 1); HandshakeLocks robot = new HandshakeLocks(pool, 1)) {
            exchange(stale, -1, 0, LONG_NANOS); // the stale session holds lock 0
            exchange(robot, -1, HandshakeLocks.served(0), LONG_NANOS); // the robot holds lock 1
            CompletableFuture<Integer> staleWaits = CompletableFuture.supplyAsync(() -> {
                try {
                    return exchange(stale, -1, 1, TimeUnit.SECONDS.toNanos(3)); // and waits for lock 1
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            Thread.sleep(200);
            // the robot waits for lock 0: a cycle, which the server breaks with an error to one of the two
            assertThat(exchange(robot, -1, HandshakeLocks.served(1), TimeUnit.SECONDS.toNanos(3))).isEqualTo(7);
            staleWaits.get(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void theTwoSidesTakeTurnsOverManyStepsWithoutPollingOrTimingOut() throws Exception {
        int steps = 300;
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB); HikariDataSource pool = pool(db);
             HandshakeLocks engine = new HandshakeLocks(pool, 1); HandshakeLocks robot = new HandshakeLocks(pool, 1)) {
            // what the clock tables would say: the wake-ups are only hints to read them
            AtomicLong sensed = new AtomicLong();
            AtomicLong served = new AtomicLong();
            AtomicLong enginePolls = new AtomicLong();
            CompletableFuture<Void> engineSide = CompletableFuture.runAsync(() -> {
                try {
                    while (served.get() < steps) {
                        long k = served.get() + 1;
                        exchange(engine, HandshakeLocks.served(k - 1), HandshakeLocks.sensed(k), LONG_NANOS);
                        if (sensed.get() >= k) {
                            served.set(k); // the iteration, committed before the next exchange gives "served"
                        } else if (k > 3) {
                            enginePolls.incrementAndGet();
                        }
                    }
                    engine.close(); // the last "served" given: the engine stops
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            long robotPolls = 0;
            for (long k = 1; k <= steps; k++) {
                sensed.set(k); // the step's answer, committed before the exchange gives "sensed"
                exchange(robot, HandshakeLocks.sensed(k), HandshakeLocks.served(k), LONG_NANOS);
                while (served.get() < k) {
                    robotPolls += k > 3 ? 1 : 0;
                    exchange(robot, HandshakeLocks.sensed(k), HandshakeLocks.served(k), LONG_NANOS);
                }
            }
            engineSide.get(30, TimeUnit.SECONDS);
            // the first steps bring the rotation in phase (a lock neither side held yet is taken at once, and
            // the side then polls); from step 4 on, every wake-up finds the other side's step there
            assertThat(robotPolls).as("robot looks that found the step not served").isZero();
            assertThat(enginePolls.get()).as("engine looks that found the step not sensed").isZero();
            assertThat(robot.count(Wake.TIMED_OUT) + engine.count(Wake.TIMED_OUT)).isZero();
            assertThat(robot.count(Wake.ACQUIRED)).isGreaterThanOrEqualTo(steps - 3);
        }
    }
}
