package org.proactiverobotics.app.mission;

import com.google.gson.JsonObject;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
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
        try {
            out.write(line.toString());
            out.write('\n');
        } catch (IOException e) {
            throw new UncheckedIOException("writing trace.jsonl", e);
        }
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}
