package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectMethod;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.junit.platform.launcher.listeners.SummaryGeneratingListener;
import org.junit.platform.launcher.listeners.TestExecutionSummary;
import org.proactiverobotics.app.Main;

/**
 * The mechanism that ends what the tests start ({@link StartedProcesses}, {@link EndsStartedProcesses}):
 * tests that start real process trees and then fail, throw or time out are run through the JUnit
 * launcher, and every process of those trees must be gone once they are over, including a
 * child whose parent had already exited.
 */
class StartedProcessesTest {

    /** The pids a test of {@link LeavingTests} started, by test name. */
    private static final Map<String, List<Long>> STARTED = new ConcurrentHashMap<>();
    /** Set while this class runs {@link LeavingTests}: on their own (a surefire run that finds them) they are skipped. */
    private static volatile boolean running;

    @Test
    void aTestThatFailsLeavesNoProcess() throws Exception {
        TestExecutionSummary summary = run("failsWithATreeRunning");
        assertThat(summary.getTestsFailedCount()).as("the test failed, as it should").isEqualTo(1);
        assertAllGone("failsWithATreeRunning", 3); // bash and its two sleeps
    }

    @Test
    void aTestThatThrowsAfterTheParentExitedLeavesNoOrphan() throws Exception {
        TestExecutionSummary summary = run("throwsAfterTheParentExited");
        assertThat(summary.getTestsFailedCount()).isEqualTo(1);
        assertAllGone("throwsAfterTheParentExited", 2); // bash (exited) and its sleep, left to init
    }

    @Test
    void aTestThatTimesOutLeavesNoProcess() throws Exception {
        TestExecutionSummary summary = run("timesOut");
        assertThat(summary.getTestsFailedCount()).isEqualTo(1);
        assertThat(summary.getFailures().get(0).getException()).hasMessageContaining("timed out");
        assertAllGone("timesOut", 2); // the robot command's JVM and bash
    }

    @Test
    void endingOneProcessEndsItsTreeAndWaitsForIt() throws Exception {
        Process bash = StartedProcesses.start(new ProcessBuilder("bash", "-c", "sleep 600 & echo $!; wait"));
        recordPids("endingOneProcess", bash, 1);
        long sleep = STARTED.get("endingOneProcess").get(1);
        List<ProcessHandle> ended = StartedProcesses.end(bash);
        assertThat(ended).extracting(ProcessHandle::pid).contains(bash.pid(), sleep);
        assertThat(bash.isAlive()).isFalse();
        assertThat(ProcessHandle.of(sleep).filter(ProcessHandle::isAlive)).isEmpty();
    }

    private static TestExecutionSummary run(String method) {
        running = true;
        try {
            LauncherDiscoveryRequest request = LauncherDiscoveryRequestBuilder.request()
                    .selectors(selectMethod(LeavingTests.class, method))
                    .build(); // configured as surefire's run is: junit-platform.properties turns EndsStartedProcesses on
            Launcher launcher = LauncherFactory.create();
            SummaryGeneratingListener listener = new SummaryGeneratingListener();
            launcher.execute(request, listener);
            TestExecutionSummary summary = listener.getSummary();
            assertThat(summary.getTestsStartedCount()).as(method + " ran").isEqualTo(1);
            return summary;
        } finally {
            running = false;
        }
    }

    private static void assertAllGone(String test, int processes) {
        List<Long> pids = STARTED.get(test);
        assertThat(pids).as("the pids " + test + " started").hasSize(processes);
        for (long pid : pids) {
            assertThat(ProcessHandle.of(pid).filter(ProcessHandle::isAlive)).as("process " + pid + " of " + test).isEmpty();
        }
    }

    /** Reads the pids a bash script prints, one a line, as the test's own. */
    private static void recordPids(String test, Process bash, int lines) throws IOException {
        List<Long> pids = new ArrayList<>(List.of(bash.pid()));
        BufferedReader in = new BufferedReader(new InputStreamReader(bash.getInputStream(), StandardCharsets.US_ASCII));
        for (int i = 0; i < lines; i++) {
            pids.add(Long.parseLong(in.readLine().strip()));
        }
        STARTED.put(test, pids);
    }

    /** Tests that end badly with processes running; run only by the tests above, through the launcher. */
    static class LeavingTests {

        @TempDir
        Path tmp;

        @Test
        void failsWithATreeRunning() throws Exception {
            Assumptions.assumeTrue(running);
            Process bash = StartedProcesses.start(new ProcessBuilder("bash", "-c",
                    "sleep 600 & echo $!; sleep 600 & echo $!; wait"));
            recordPids("failsWithATreeRunning", bash, 2);
            assertThat(bash.isAlive()).as("a failing assertion while the tree runs").isFalse();
        }

        @Test
        void throwsAfterTheParentExited() throws Exception {
            Assumptions.assumeTrue(running);
            // the parent lives long enough to be looked at, then exits as a failed `set -e` script does
            Process bash = StartedProcesses.start(new ProcessBuilder("bash", "-c", "sleep 600 & echo $!; sleep 1; exit 3"));
            recordPids("throwsAfterTheParentExited", bash, 1);
            assertThat(bash.waitFor(30, TimeUnit.SECONDS)).isTrue();
            assertThat(ProcessHandle.of(STARTED.get("throwsAfterTheParentExited").get(1))).as("the orphan runs on")
                    .hasValueSatisfying(h -> assertThat(h.isAlive()).isTrue());
            throw new IllegalStateException("a test that throws");
        }

        @Test
        @Timeout(value = 5, unit = TimeUnit.SECONDS)
        void timesOut() throws Exception {
            Assumptions.assumeTrue(running);
            // the app's robot command waiting for a database that never comes: a JVM that would wait a minute
            String javaCommand = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            Process bash = StartedProcesses.start(new ProcessBuilder("bash", "-c", "\"$0\" -cp \"$1\" "
                    + Main.class.getName() + " robot --world reference-arena"
                    + " --db jdbc:mariadb://127.0.0.1:9/none --wait-s 600 --out \"$2\" > /dev/null 2>&1 & echo $!; wait",
                    javaCommand, System.getProperty("java.class.path"), tmp.resolve("out").toString()));
            recordPids("timesOut", bash, 1);
            Thread.sleep(Duration.ofMinutes(5).toMillis());
        }
    }
}
