package org.proactiverobotics.app.deploy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.concurrent.TimeUnit;

/**
 * A file whose modification time says the loop of a long-running command is alive, for a
 * container health check ({@code find FILE -mmin -1}). Touched at most every few seconds.
 */
public final class Heartbeat {

    private static final long EVERY_NANOS = TimeUnit.SECONDS.toNanos(5);

    private final Path file;
    private long lastNanos;
    private boolean started;

    /** @param file the file to touch, or null for none */
    public Heartbeat(Path file) {
        this.file = file;
    }

    /** Touches the file when the last touch is a few seconds old; never fails the loop. */
    public void beat() {
        if (file == null) {
            return;
        }
        long now = System.nanoTime();
        if (started && now - lastNanos < EVERY_NANOS) {
            return;
        }
        started = true;
        lastNanos = now;
        try {
            if (!Files.exists(file)) {
                Files.createFile(file);
            }
            Files.setLastModifiedTime(file, FileTime.fromMillis(System.currentTimeMillis()));
        } catch (IOException e) {
            // a health check that cannot see the file reports it; the loop goes on
        }
    }
}
