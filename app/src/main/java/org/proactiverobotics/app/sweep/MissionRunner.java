package org.proactiverobotics.app.sweep;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BooleanSupplier;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.robot.ScenarioPlugins;

/**
 * Runs one mission of a sweep into its own folder, as {@code run} would (the same {@link Mission},
 * report.json written the same way), on an embedded H2 database of its own that is dropped
 * afterwards, or over the direct link. Also leaves world.json there: the world with the seed used,
 * so {@code run --world <folder>/world.json} runs the mission again. Safe to call from many threads.
 */
public final class MissionRunner {

    /** Writes report.json as {@code run} writes it. */
    @FunctionalInterface
    public interface ReportWriter {
        /**
         * @param report the report
         * @param file   report.json
         * @throws IOException when it cannot be written
         */
        void write(MissionReport report, Path file) throws IOException;
    }

    /** Thrown from the step hook to end a mission early when the sweep is stopped (Ctrl-C). */
    public static final class Cancelled extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Cancelled() {
            super("the sweep was stopped", null, false, false);
        }
    }

    private static final AtomicLong DATABASES = new AtomicLong();

    private final MissionOptions.Link link;
    private final ScenarioPlugins plugins;
    private final ReportWriter reportWriter;
    private final BooleanSupplier stopped;
    private boolean mcap;

    /**
     * @param link         the link every mission uses
     * @param plugins      the plug-in scenarios every mission loads
     * @param reportWriter writes report.json
     * @param stopped      true once the sweep is stopped: a running mission ends at its next step
     */
    public MissionRunner(MissionOptions.Link link, ScenarioPlugins plugins, ReportWriter reportWriter,
                         BooleanSupplier stopped) {
        this.link = link;
        this.plugins = plugins;
        this.reportWriter = reportWriter;
        this.stopped = stopped;
    }

    /**
     * @param enabled whether each mission also writes run.mcap in its folder
     * @return this runner
     */
    public MissionRunner mcap(boolean enabled) {
        this.mcap = enabled;
        return this;
    }

    /**
     * Runs the mission; whatever it throws becomes its result, except a stop.
     *
     * @param mission the mission
     * @param dir     its folder (created here)
     * @return its result
     * @throws Cancelled when the sweep was stopped before the mission ended
     */
    public MissionResult run(SweepMission mission, Path dir) {
        long start = System.nanoTime();
        String name = "proactive_sweep_" + ProcessHandle.current().pid() + "_" + DATABASES.incrementAndGet();
        // H2 must not close its databases in its own shutdown hook: on Ctrl-C the running missions end first, at their next step
        String url = Databases.embeddedH2Url(name) + ";DB_CLOSE_ON_EXIT=FALSE";
        try {
            Files.createDirectories(dir);
            Files.writeString(dir.resolve("world.json"), WorldJson.of(mission.world()), StandardCharsets.UTF_8);
            MissionOptions options = new MissionOptions(mission.world(), url, "sa", "", mission.strategy(), 1, link,
                    plugins, mission.noise());
            Mission run = new Mission(options).mcap(mcap).onStep(sim -> {
                if (stopped.getAsBoolean()) {
                    throw new Cancelled();
                }
            });
            MissionReport report = run.run(dir);
            reportWriter.write(report, dir.resolve("report.json"));
            return MissionResult.of(mission, report);
        } catch (Cancelled e) {
            throw e;
        } catch (Exception | StackOverflowError e) { // a fault of this mission only: recorded, the sweep goes on
            return MissionResult.error(mission, e, (System.nanoTime() - start) / 1e9);
        } finally {
            if (link == MissionOptions.Link.JDBC) {
                drop(url);
            }
        }
    }

    /** The in-memory database outlives its pools (DB_CLOSE_DELAY=-1): shut it down, or a sweep keeps them all. */
    private static void drop(String url) {
        try (Connection c = DriverManager.getConnection(url, "sa", ""); Statement s = c.createStatement()) {
            s.execute("SHUTDOWN");
        } catch (SQLException e) {
            // already closed: nothing left to free
        }
    }
}
