package org.proactiverobotics.app.mission;

import com.google.gson.JsonObject;
import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.Suggestion;

/**
 * Writes trace.jsonl: one JSON object per engine decision with the CommandArray's suggestions,
 * the winner and the command sent.
 */
final class TraceWriter implements AutoCloseable {

    private final BufferedWriter out;
    /** The first write error, reported at close: a full disk must not fail the decision rule. */
    private IOException failure;

    TraceWriter(Path file) throws IOException {
        this.out = Files.newBufferedWriter(file);
    }

    void decision(long iteration, long simTimeMs, CommandArray suggestions, Suggestion winner) {
        JsonObject line = new JsonObject();
        line.addProperty("iteration", iteration);
        line.addProperty("simTimeS", simTimeMs / 1000.0);
        JsonObject entered = new JsonObject();
        for (int slot = 0; slot < suggestions.size(); slot++) {
            Suggestion s = suggestions.get(slot);
            if (s != null) {
                entered.addProperty(s.scenario(), s.command());
            }
        }
        line.add("suggestions", entered);
        line.addProperty("winner", winner.scenario());
        line.addProperty("command", winner.command());
        if (failure != null) {
            return;
        }
        try {
            out.write(line.toString());
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
