package org.proactiverobotics.app.deploy;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * An output directory a command creates before it touches the database (so that a bad --out is
 * bad input, found at once), and takes back when the command fails before writing anything: a
 * failed command leaves nothing behind. A folder that holds something already is refused unless
 * the user says {@code --force}: an earlier run's files are not overwritten by surprise.
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

    /**
     * Why {@code --out} cannot be used, checked before anything is written: a file where the
     * folder (or one of its parents) should be, or a folder that is not empty without {@code --force}.
     *
     * @param dir   the {@code --out} folder
     * @param force whether the user allows writing into a folder that is not empty
     * @return one line saying what is wrong and what to do, or null when the folder may be used
     */
    public static String refusal(Path dir, boolean force) {
        if (Files.isDirectory(dir)) {
            try (Stream<Path> entries = Files.list(dir)) {
                return entries.findAny().isPresent() && !force ? "--out " + dir
                        + " exists and is not empty: give --force to write into it anyway, or another folder" : null;
            } catch (IOException e) {
                return "--out " + dir + ": cannot read the folder (" + reason(e) + ")";
            }
        }
        if (Files.exists(dir)) {
            return "--out " + dir + " is a file, not a folder: give a folder that does not exist yet or is empty";
        }
        for (Path p = dir.toAbsolutePath().normalize().getParent(); p != null; p = p.getParent()) {
            if (Files.exists(p)) {
                return Files.isDirectory(p) ? null
                        : "--out " + dir + ": " + p + " is a file, not a folder: give a folder that does not exist yet";
            }
        }
        return null;
    }

    /**
     * @param e a file system failure
     * @return what went wrong in a few words (the JDK's message of some is only the path)
     */
    public static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such file or folder";
        }
        if (e instanceof FileAlreadyExistsException) {
            return "a file of that name is in the way";
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
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
