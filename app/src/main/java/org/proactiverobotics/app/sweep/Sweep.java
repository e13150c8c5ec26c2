package org.proactiverobotics.app.sweep;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;

/**
 * Runs a sweep's missions in this JVM, {@code jobs} at a time, each into its own folder; every
 * finished mission goes to results.csv at once and to the progress display. A mission's fault is
 * its row; {@link #stop()} (Ctrl-C) lets no new mission start and ends the running ones at their
 * next step, their partial folders removed, and the rows done so far stay.
 */
public final class Sweep {

    private final List<SweepMission> missions;
    private final Path outDir;
    private final int jobs;
    private final AtomicBoolean stopped = new AtomicBoolean();
    private final CountDownLatch finished = new CountDownLatch(1);
    private final AtomicReference<UncheckedIOException> outputFailure = new AtomicReference<>();
    /** robots.csv, when the sweep has worlds with several robots; null otherwise. */
    private volatile RobotsCsv robotsCsv;

    /**
     * @param missions the missions, in order
     * @param outDir   the sweep's folder (exists)
     * @param jobs     missions at a time, at least 1
     */
    public Sweep(List<SweepMission> missions, Path outDir, int jobs) {
        if (jobs < 1) {
            throw new IllegalArgumentException("jobs must be >= 1: " + jobs);
        }
        this.missions = List.copyOf(missions);
        this.outDir = outDir;
        this.jobs = jobs;
    }

    /**
     * Also writes each finished mission's robots to robots.csv (worlds with several robots).
     *
     * @param csv robots.csv
     * @return this
     */
    public Sweep robots(RobotsCsv csv) {
        this.robotsCsv = csv;
        return this;
    }

    /** @return whether {@link #stop()} was called */
    public boolean isStopped() {
        return stopped.get();
    }

    /** Stops the sweep: no mission starts any more, and running ones end at their next step. */
    public void stop() {
        stopped.set(true);
    }

    /**
     * Waits for {@link #run} to return after a stop.
     *
     * @param timeoutMs at most this long, milliseconds
     * @throws InterruptedException when interrupted while waiting
     */
    public void awaitFinished(long timeoutMs) throws InterruptedException {
        finished.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    /**
     * Runs every mission (or until stopped).
     *
     * @param runner   runs one mission; built with {@link #isStopped} as its stop check
     * @param csv      results.csv
     * @param progress the progress display
     * @return the results of the missions that finished, in the missions' order
     * @throws IOException when results.csv cannot be written (the sweep stops)
     */
    public List<MissionResult> run(MissionRunner runner, ResultsCsv csv, SweepProgress progress) throws IOException {
        List<MissionResult> results = new ArrayList<>();
        AtomicInteger thread = new AtomicInteger();
        ExecutorService pool = Executors.newFixedThreadPool(jobs, r -> {
            Thread t = new Thread(r, "sweep-" + thread.incrementAndGet());
            t.setDaemon(true); // Ctrl-C must not wait for a mission that ignores the stop
            return t;
        });
        try {
            for (SweepMission mission : missions) {
                pool.execute(() -> runOne(mission, runner, csv, progress, results));
            }
            pool.shutdown();
            while (!pool.awaitTermination(1, TimeUnit.SECONDS)) {
                // missions still running
            }
        } catch (InterruptedException e) {
            stop();
            pool.shutdownNow();
            Thread.currentThread().interrupt();
        } finally {
            finished.countDown();
        }
        if (outputFailure.get() != null) {
            throw outputFailure.get().getCause();
        }
        synchronized (results) {
            results.sort(Comparator.comparingInt(r -> r.mission().index()));
            return List.copyOf(results);
        }
    }

    private void runOne(SweepMission mission, MissionRunner runner, ResultsCsv csv, SweepProgress progress,
                        List<MissionResult> results) {
        if (stopped.get()) {
            return;
        }
        Path dir = outDir.resolve(mission.folder());
        MissionResult result;
        try {
            result = runner.run(mission, dir);
        } catch (MissionRunner.Cancelled e) {
            deleteQuietly(dir);
            return;
        }
        try {
            csv.append(result);
            if (robotsCsv != null) {
                robotsCsv.append(result);
            }
        } catch (UncheckedIOException e) {
            outputFailure.compareAndSet(null, e);
            stop();
            return;
        }
        synchronized (results) {
            results.add(result);
        }
        progress.finished(result);
    }

    private static void deleteQuietly(Path dir) {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            // a partial folder left behind is harmless: its mission has no row
        }
    }
}
