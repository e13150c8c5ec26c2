package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** docs/engine.md, the two queues: the two FIFO queues, generation order, outside rules. */
class IterationTest {

    private final Log log = new Log();

    private ProactiveEngine engine() {
        return ProactiveEngine.builder().service(Log.class, log).build();
    }

    private List<String> actionsRun() {
        return log.take().stream().filter(e -> e.endsWith(":actions")).map(e -> e.substring(0, e.indexOf(':'))).toList();
    }

    /** Generates, in order, a clone of itself and then a one-shot child named after it. */
    static final class Parent extends Rule {
        String id;

        private Parent() {
        }

        Parent(String id) {
            this.id = id;
        }

        @Override
        public String scenario() {
            return "test";
        }

        @Override
        protected void actions(RuleContext ctx) {
            ctx.service(Log.class).add(id + ":actions");
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
            ctx.generate(Probe.once(id + ctx.iteration()));
        }
    }

    @Test
    void fifoOrderOfGenerationIsKeptAcrossIterations() {
        ProactiveEngine engine = engine();
        engine.startFresh(new Parent("a"), new Parent("b"), new Parent("c"));
        engine.runIteration();
        assertThat(actionsRun()).containsExactly("a", "b", "c");
        engine.runIteration();
        assertThat(actionsRun()).containsExactly("a", "a1", "b", "b1", "c", "c1");
        engine.runIteration();
        assertThat(actionsRun()).containsExactly("a", "a2", "b", "b2", "c", "c2");
    }

    @Test
    void rulesGeneratedInAnIterationRunOnlyInTheNext() {
        ProactiveEngine engine = engine();
        engine.startFresh(new Parent("a"));
        IterationSummary first = engine.runIteration();
        assertThat(first.rulesRun()).isEqualTo(1);
        assertThat(first.rulesGenerated()).isEqualTo(2);
        assertThat(engine.nextQueue()).extracting(Rule::name).containsExactly("Parent", "a1");
        assertThat(engine.runIteration().rulesRun()).isEqualTo(2);
    }

    @Test
    void aRuleSubmittedBetweenIterationsRunsInTheNextIteration() {
        ProactiveEngine engine = engine();
        engine.startFresh(Probe.forever("p"));
        engine.runIteration();
        engine.submit(Probe.once("outside"));
        assertThat(engine.iteration()).isEqualTo(1);
        engine.runIteration();
        assertThat(actionsRun()).containsExactly("p", "p", "outside");
    }

    @Test
    void submissionsFromAnotherThreadDuringAnIterationJoinNextQueueAfterGeneratedRules() throws Exception {
        CountDownLatch running = new CountDownLatch(1);
        CountDownLatch submittedLatch = new CountDownLatch(1);
        Rule blocker = new Rule() {
            @Override
            public String scenario() {
                return "test";
            }

            @Override
            protected void actions(RuleContext ctx) throws Exception {
                running.countDown();
                assertThat(submittedLatch.await(5, TimeUnit.SECONDS)).isTrue();
            }

            @Override
            protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
                ctx.generate(Probe.once("generated"));
            }
        };
        ProactiveEngine engine = engine();
        engine.startFresh(blocker);
        Thread other = new Thread(() -> {
            try {
                running.await();
                engine.submit(Probe.once("outside"));
                submittedLatch.countDown();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        other.start();
        IterationSummary first = engine.runIteration();
        other.join();
        assertThat(first.rulesSubmitted()).isEqualTo(1);
        assertThat(engine.nextQueue()).extracting(Rule::name).containsExactly("generated", "outside");
        engine.runIteration();
        assertThat(actionsRun()).containsExactly("generated", "outside");
    }

    @Test
    void concurrentSubmissionsAreNeitherLostNorRunTwice() throws Exception {
        ProactiveEngine engine = engine();
        engine.startFresh();
        List<Thread> threads = new ArrayList<>();
        for (int t = 0; t < 4; t++) {
            int id = t;
            threads.add(new Thread(() -> {
                for (int i = 0; i < 500; i++) {
                    engine.submit(Probe.once("t" + id + "-" + i));
                }
            }));
        }
        threads.forEach(Thread::start);
        int run = 0;
        while (threads.stream().anyMatch(Thread::isAlive)) {
            run += engine.runIteration().rulesRun();
        }
        for (Thread t : threads) {
            t.join();
        }
        run += engine.runIteration().rulesRun();
        run += engine.runIteration().rulesRun();
        assertThat(run).isEqualTo(2000);
        assertThat(actionsRun()).hasSize(2000).doesNotHaveDuplicates();
    }

    @Test
    void iterationsAreNumberedFromOneAndNeedAStart() {
        ProactiveEngine engine = engine();
        assertThatThrownBy(engine::runIteration).isInstanceOf(IllegalStateException.class).hasMessageContaining("start");
        engine.startFresh();
        assertThat(engine.iteration()).isZero();
        assertThat(engine.runIteration().iteration()).isEqualTo(1);
        assertThat(engine.runIteration().iteration()).isEqualTo(2);
    }
}
