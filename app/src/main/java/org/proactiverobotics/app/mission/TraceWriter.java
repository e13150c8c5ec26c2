package org.proactiverobotics.app.mission;

import com.google.gson.Strictness;
import com.google.gson.stream.JsonWriter;
import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.proactiverobotics.app.replay.TraceStep;

/**
 * Writes trace.jsonl: one JSON object per engine decision (see {@link TraceStep#write} and
 * docs/report.md).
 */
final class TraceWriter implements AutoCloseable {

    private final BufferedWriter out;
    /** One writer for the whole file, lenient so that it takes one object per line. */
    private final JsonWriter json;
    /** The first write error, reported at close: a full disk must not fail the mission. */
    private IOException failure;

    TraceWriter(Path file) throws IOException {
        this.out = Files.newBufferedWriter(file);
        this.json = new JsonWriter(out);
        json.setStrictness(Strictness.LENIENT);
    }

    void write(TraceStep step) {
        write(step, null);
    }

    /**
     * @param step    the step
     * @param robotId its robot's id in a world with several robots, or null (a one-robot world: no {@code robot} key)
     */
    void write(TraceStep step, Integer robotId) {
        if (failure != null) {
            return;
        }
        try {
            step.write(json, robotId); // straight into the file's buffer: no String per line
            out.write('\n');
        } catch (IOException e) {
            failure = e;
        }
    }

    @Override
    public void close() throws IOException {
        try {
            out.close();
        } catch (IOException e) {
            if (failure == null) {
                failure = e;
            }
        }
        if (failure != null) {
            throw new IOException("writing trace.jsonl: " + failure.getMessage(), failure);
        }
    }
}
