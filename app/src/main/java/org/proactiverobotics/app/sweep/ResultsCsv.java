package org.proactiverobotics.app.sweep;

import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVPrinter;
import org.proactiverobotics.app.mission.PoseError;

/**
 * results.csv: one row per mission, written and flushed as each mission finishes (from any
 * worker thread), so that an interrupted sweep keeps every row it finished.
 */
public final class ResultsCsv implements Closeable {

    /** The columns, in order (the pose error's last, added after the others: a reader by position keeps working). */
    public static final List<String> COLUMNS = List.of("world", "strategy", "noise", "seed", "outcome", "success",
            "checkpointsReached", "checkpointsTotal", "simTimeS", "wallTimeS", "distanceM", "collisions", "minBattery",
            "recharges", "worldKind", "reason", "mission", "poseErrorMeanM", "poseErrorMaxM", "headingErrorMeanRad",
            "headingErrorMaxRad");

    /** The file's format (the header aside): RFC 4180 with a bare newline between rows. */
    static final CSVFormat FORMAT = CSVFormat.DEFAULT.builder().setRecordSeparator("\n").get();

    private final CSVPrinter printer;

    /**
     * Creates the file and writes the header.
     *
     * @param file results.csv
     * @throws IOException when it cannot be written
     */
    public ResultsCsv(Path file) throws IOException {
        Writer writer = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        this.printer = new CSVPrinter(writer, FORMAT.builder().setHeader(COLUMNS.toArray(String[]::new)).get());
        printer.flush();
    }

    /**
     * Appends a row and flushes it to the file.
     *
     * @param r the mission's result
     * @throws UncheckedIOException when the file cannot be written
     */
    public synchronized void append(MissionResult r) {
        SweepMission m = r.mission();
        PoseError pose = r.poseError(); // null: empty cells
        try {
            printer.printRecord(m.world().name(), m.strategy().name(), m.noise().label(), m.seed(), r.outcome(), r.success(),
                    r.checkpointsReached(), r.checkpointsTotal(), r.simTimeS(), r.wallTimeS(), r.distanceM(), r.collisions(),
                    r.minBattery(), r.recharges(), m.worldKind(), r.reason(), m.folder(),
                    pose == null ? null : pose.meanM(), pose == null ? null : pose.maxM(),
                    pose == null ? null : pose.meanHeadingRad(), pose == null ? null : pose.maxHeadingRad());
            printer.flush();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Appends a row as read from another results.csv (a shard's, when merging), value for value.
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
