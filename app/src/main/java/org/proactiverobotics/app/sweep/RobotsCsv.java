package org.proactiverobotics.app.sweep;

import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.apache.commons.csv.CSVPrinter;
import org.proactiverobotics.app.mission.PoseError;
import org.proactiverobotics.app.mission.RobotReport;

/**
 * robots.csv, beside results.csv when a sweep has worlds with several robots: one row per robot of each such
 * mission (its own mission's outcome, from report.json's {@code robots}), written and flushed as each mission
 * finishes. results.csv keeps one row per mission, the run as a whole (success only when every robot
 * accomplished); {@code mission} joins the two files.
 */
public final class RobotsCsv implements Closeable {

    /** The file's name in the sweep's folder. */
    public static final String FILE_NAME = "robots.csv";

    /** The columns, in order. */
    public static final List<String> COLUMNS = List.of("mission", "world", "strategy", "noise", "seed", "robot",
            "outcome", "success", "checkpointsReached", "checkpointsTotal", "endSimTimeS", "distanceM", "collisions",
            "robotCollisions", "minClearanceM", "minBattery", "recharges", "reason", "poseErrorMeanM", "poseErrorMaxM");

    private final CSVPrinter printer;

    /**
     * Creates the file and writes the header.
     *
     * @param file robots.csv
     * @throws IOException when it cannot be written
     */
    public RobotsCsv(Path file) throws IOException {
        Writer writer = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        this.printer = new CSVPrinter(writer, ResultsCsv.FORMAT.builder().setHeader(COLUMNS.toArray(String[]::new)).get());
        printer.flush();
    }

    /**
     * Appends a row per robot of the mission (none for a one-robot mission or one that threw) and flushes them.
     *
     * @param r the mission's result
     * @throws UncheckedIOException when the file cannot be written
     */
    public synchronized void append(MissionResult r) {
        SweepMission m = r.mission();
        try {
            for (RobotReport robot : r.robots()) {
                PoseError pose = robot.poseError();
                printer.printRecord(m.folder(), m.world().name(), m.strategy().name(), m.noise().label(), m.seed(),
                        robot.id(), robot.outcome(), robot.success(), robot.checkpointsReached(),
                        robot.checkpointsTotal(), robot.endSimTimeS(), robot.distanceM(), robot.collisions(),
                        robot.robotCollisions(), robot.minClearanceM(), robot.minBattery(), robot.recharges(),
                        robot.reason(), pose == null ? null : pose.meanM(), pose == null ? null : pose.maxM());
            }
            printer.flush();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Appends a row as read from another robots.csv (a shard's, when merging), value for value.
     *
     * @param values the row's values, in {@link #COLUMNS}' order
     * @throws UncheckedIOException when the file cannot be written
     */
    public synchronized void appendValues(List<String> values) {
        try {
            printer.printRecord(values);
            printer.flush();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public synchronized void close() throws IOException {
        printer.close();
    }
}
