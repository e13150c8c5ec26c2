package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.persistence.JdbcStateStore;

/** Many engines (one per robot) on one database save their first state at the same moment. */
class ConcurrentFirstSaveTest {

    private static final int ENGINES = 16;

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void enginesStartingTogetherDoNotDeadlockOnTheirFirstSave(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            ExecutorService pool = Executors.newFixedThreadPool(ENGINES);
            try {
                CountDownLatch start = new CountDownLatch(1);
                List<Future<Long>> saved = new ArrayList<>();
                for (int robot = 1; robot <= ENGINES; robot++) {
                    int robotId = robot;
                    saved.add(pool.submit(() -> {
                        ProactiveEngine engine = ProactiveEngine.builder().robotId(robotId)
                                .store(new JdbcStateStore(db.dataSource())).build();
                        engine.start(new Workload.Counter("c", 0));
                        start.await();
                        for (int i = 0; i < 3; i++) {
                            engine.runIteration();
                        }
                        return engine.iteration();
                    }));
                }
                start.countDown();
                for (Future<Long> f : saved) {
                    assertThat(f.get(60, TimeUnit.SECONDS)).isEqualTo(3);
                }
            } finally {
                pool.shutdownNow();
            }
            assertThat(db.count("engine_state")).isEqualTo(ENGINES);
        }
    }
}
