package org.proactiverobotics.app.deploy;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * SIGTERM / Ctrl-C for a long-running command: a JVM shutdown hook raises the stop flag, waits
 * for the command to end its current step or iteration (state saved) and to call
 * {@link #finished(int)}, then ends the JVM with that exit code (0 for the engine: a stop that
 * was asked for is a clean exit, not the JVM's 143). A command that ends on its own calls
 * {@link #finished(int)} before exiting and the hook leaves it alone.
 */
public final class ShutdownSignal {

    private static final long GRACE_S = 20;

    private final CountDownLatch done = new CountDownLatch(1);
    private volatile boolean stopRequested;
    private volatile boolean finished;
    /** Until the command says otherwise, a stop that cannot finish in time is a failure (docs/command-line.md, exit codes). */
    private volatile int exitCode = 1;
    private volatile Runnable onStop = () -> { };

    private ShutdownSignal() {
    }

    /** @return a signal whose shutdown hook is installed */
    public static ShutdownSignal install() {
        ShutdownSignal signal = new ShutdownSignal();
        Runtime.getRuntime().addShutdownHook(new Thread(signal::shutdown, "proactive-shutdown"));
        return signal;
    }

    /** @param action run when a stop is requested (ask the loop to stop); at once if already requested */
    public void onStop(Runnable action) {
        this.onStop = action;
        if (stopRequested) {
            action.run();
        }
    }

    /** @return whether a stop was requested */
    public boolean stopRequested() {
        return stopRequested;
    }

    /**
     * The command is done: after a stop request the JVM then ends with this code.
     *
     * @param code the command's exit code
     */
    public void finished(int code) {
        exitCode = code;
        finished = true;
        done.countDown();
    }

    private void shutdown() {
        if (finished) {
            return; // ended on its own: System.exit's code stands
        }
        stopRequested = true;
        onStop.run();
        try {
            done.await(GRACE_S, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        System.out.flush();
        System.err.flush();
        // System.exit from the command's thread would block while this hook runs: end here instead.
        Runtime.getRuntime().halt(exitCode);
    }
}
