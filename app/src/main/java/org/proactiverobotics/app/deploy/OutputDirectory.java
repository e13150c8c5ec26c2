package org.proactiverobotics.app.deploy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * An output directory a command creates before it touches the database (so that a bad --out is
 * bad input, found at once), and takes back when the command fails before writing anything: a
 * failed command leaves nothing behind.
 */
public final class OutputDirectory {

    private final Path path;
    private final List<Path> created;

    private OutputDirectory(Path path, List<Path> created) {
        this.path = path;
        this.created = created;
    }

    /**
     * Creates the directory and its missing parents.
     *
     * @param dir the directory
     * @return the directory, remembering which parts it created
     * @throws IOException when it cannot be created
     */
    public static OutputDirectory create(Path dir) throws IOException {
        List<Path> missing = new ArrayList<>(); // deepest first
        for (Path p = dir.toAbsolutePath().normalize(); p != null && !Files.exists(p); p = p.getParent()) {
            missing.add(p);
        }
        Files.createDirectories(dir);
        return new OutputDirectory(dir, missing);
    }

    /** @return the directory */
    public Path path() {
        return path;
    }

    /** Deletes the directories {@link #create} made, as long as they are still empty. */
    public void removeIfEmpty() {
        for (Path p : created) {
            try {
                Files.deleteIfExists(p);
            } catch (IOException e) { // not empty (something was written) or not ours to delete: keep it
                return;
            }
        }
    }
}
