package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.Collection;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;

/** The periodic runner: a configurable period, a clean start and a stop that lets the iteration finish and save. */
class PeriodicRunnerTest {

    private static void waitFor(java.util.function.BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + Duration.ofSeconds(5).toNanos();
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("timed out").isLessThan(deadline);
            Thread.sleep(2);
        }
    }

    @Test
    void runsIterationsEveryPeriodAndStopsAfterASavedIteration() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            JdbcStateStore store = new JdbcStateStore(db.dataSource());
            ProactiveEngine engine = ProactiveEngine.builder().store(store).build();
            engine.startFresh(new Workload.Counter("a", 0));
            PeriodicRunner runner = new PeriodicRunner(engine, Duration.ofMillis(5)).start();
            assertThat(runner.isRunning()).isTrue();
            waitFor(() -> engine.iteration() >= 5);
            runner.stop();
            assertThat(runner.isRunning()).isFalse();
            long stoppedAt = engine.iteration();
            Thread.sleep(30);
            assertThat(engine.iteration()).as("no iteration after stop").isEqualTo(stoppedAt);
            assertThat(store.load(1).orElseThrow().iteration()).as("the last iteration was saved").isEqualTo(stoppedAt);
            assertThat(runner.error()).isEmpty();
        }
    }

    @Test
    void aListenerMayStopTheRunnerFromTheEngineThread() throws Exception {
        PeriodicRunner[] runner = new PeriodicRunner[1];
        ProactiveEngine engine = ProactiveEngine.builder().listener(new IterationListener() {
            @Override
            public void iterationEnded(IterationSummary summary) {
                if (summary.iteration() == 3) {
                    runner[0].stop(); // on the runner's own thread: returns at once, no deadlock
                }
            }
        }).build();
        engine.startFresh(Probe.forever("p"));
        runner[0] = new PeriodicRunner(engine, Duration.ofMillis(2));
        runner[0].start();
        waitFor(() -> !runner[0].isRunning());
        assertThat(engine.iteration()).isEqualTo(3);
        runner[0].stop();
    }

    @Test
    void aFailingSaveStopsTheRunnerAndIsReported() throws Exception {
        StateStore broken = new StateStore() {
            @Override
            public Optional<SavedState> load(int robotId) {
                return Optional.empty();
            }

            @Override
            public void save(int robotId, long iteration, Collection<Rule> nextQueue, SharedMemory memory, List<RuleFailure> failures) {
                if (iteration == 2) {
                    throw new StateStoreException("database gone");
                }
            }

            @Override
            public void clear(int robotId) {
            }
        };
        ProactiveEngine engine = ProactiveEngine.builder().store(broken).build();
        engine.startFresh(Probe.forever("p"));
        PeriodicRunner runner = new PeriodicRunner(engine, Duration.ofMillis(2)).start();
        waitFor(() -> !runner.isRunning());
        assertThat(runner.error()).get().extracting(Throwable::getMessage).isEqualTo("database gone");
        assertThat(engine.iteration()).isEqualTo(2);
        runner.stop();
    }
}
