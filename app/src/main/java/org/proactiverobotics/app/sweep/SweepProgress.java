package org.proactiverobotics.app.sweep;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;

/**
 * How far a sweep is: on a terminal, a progress bar (done/total, failures so far, ETA); otherwise
 * (a log, CI) one line every few seconds. Thread-safe.
 */
public abstract class SweepProgress implements AutoCloseable {

    /** Missions finished. */
    protected final AtomicInteger done = new AtomicInteger();
    /** Missions finished that were not accomplished. */
    protected final AtomicInteger failed = new AtomicInteger();
    /** Missions in the sweep. */
    protected final int total;

    private SweepProgress(int total) {
        this.total = total;
    }

    /**
     * @param total    missions in the sweep
     * @param terminal whether standard error is a terminal
     * @param lines    where the periodic lines go when it is not
     * @return the progress display
     */
    public static SweepProgress start(int total, boolean terminal, PrintWriter lines) {
        return terminal ? new Bar(total) : new Lines(total, lines, Duration.ofSeconds(5));
    }

    /** @param result a mission that just finished */
    public void finished(MissionResult result) {
        done.incrementAndGet();
        if (!result.success()) {
            failed.incrementAndGet();
        }
        shown();
    }

    /** Shows the new count. */
    protected abstract void shown();

    @Override
    public abstract void close();

    /** The progressbar library's bar on standard error. */
    private static final class Bar extends SweepProgress {
        private final ProgressBar bar;

        Bar(int total) {
            super(total);
            this.bar = new ProgressBarBuilder().setTaskName("sweep").setInitialMax(total).setStyle(ProgressBarStyle.ASCII)
                    .setUpdateIntervalMillis(500).setConsumer(new ConsoleProgressBarConsumer(System.err))
                    .setUnit(" missions", 1).build();
            bar.setExtraMessage("0 failed");
        }

        @Override
        protected synchronized void shown() {
            bar.stepTo(done.get());
            bar.setExtraMessage(failed.get() + " failed");
        }

        @Override
        public void close() {
            bar.close();
        }
    }

    /** A line every period, and one at the end. */
    private static final class Lines extends SweepProgress {
        private final PrintWriter out;
        private final long startNs = System.nanoTime();
        private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "sweep-progress");
            t.setDaemon(true);
            return t;
        });

        Lines(int total, PrintWriter out, Duration period) {
            super(total);
            this.out = out;
            timer.scheduleAtFixedRate(this::line, period.toMillis(), period.toMillis(), TimeUnit.MILLISECONDS);
        }

        @Override
        protected void shown() {
            // the timer prints
        }

        private synchronized void line() {
            int d = done.get();
            double elapsedS = (System.nanoTime() - startNs) / 1e9;
            String eta = d == 0 ? "?" : clock(elapsedS / d * (total - d));
            out.printf(Locale.ROOT, "sweep: %d/%d missions, %d failed, %s elapsed, about %s left%n", d, total, failed.get(),
                    clock(elapsedS), eta);
            out.flush();
        }

        private static String clock(double seconds) {
            long s = Math.round(seconds);
            return String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60);
        }

        @Override
        public void close() {
            timer.shutdownNow();
            line();
        }
    }
}
