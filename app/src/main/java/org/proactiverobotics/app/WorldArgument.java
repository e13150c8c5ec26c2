package org.proactiverobotics.app;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.List;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.WorldValidationException;

/**
 * What {@code --world} names, for every command that takes it ({@code run}, {@code robot}, {@code validate}):
 * a file that exists wins; otherwise the name of a world bundled in the jar ({@code low-battery}, with or
 * without {@code .json}). A value that is neither, or a file that is invalid, is reported on standard error.
 */
final class WorldArgument {

    private WorldArgument() {
    }

    /**
     * @param value the {@code --world} value, or null for the default world
     * @param err   where problems are reported
     * @return the validated world, or null when a problem was reported (the command exits 2)
     */
    static WorldSpec load(String value, PrintWriter err) {
        try {
            return resolve(value);
        } catch (NoSuchWorld e) {
            err.println(e.getMessage());
        } catch (WorldValidationException e) {
            err.println(e.report());
        }
        err.flush();
        return null;
    }

    /**
     * @param value the {@code --world} value, or null for the default world
     * @return the validated world
     * @throws NoSuchWorld                when the value is neither a file nor a bundled world's name
     * @throws WorldValidationException when the file (or bundled world) is invalid
     */
    static WorldSpec resolve(String value) {
        if (value == null) {
            return WorldFiles.defaultWorld();
        }
        if (exists(value)) {
            return WorldFiles.load(Path.of(value));
        }
        String name = value.endsWith(".json") ? value.substring(0, value.length() - 5) : value;
        List<String> bundled = WorldFiles.bundledNames();
        if (bundled.contains(name)) {
            return WorldFiles.bundled(name);
        }
        throw new NoSuchWorld(value + ": no such file, and no bundled world of that name; bundled worlds: "
                + String.join(", ", bundled));
    }

    private static boolean exists(String value) {
        try {
            return Files.exists(Path.of(value));
        } catch (InvalidPathException e) {
            return false;
        }
    }

    /** {@code --world} names neither a file nor a bundled world. */
    static final class NoSuchWorld extends RuntimeException {
        private static final long serialVersionUID = 1L;

        NoSuchWorld(String message) {
            super(message);
        }
    }

    /** The bundled worlds' names, for {@code --help} ({@code ${COMPLETION-CANDIDATES}}). */
    static final class BundledNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return WorldFiles.bundledNames().iterator();
        }
    }
}
