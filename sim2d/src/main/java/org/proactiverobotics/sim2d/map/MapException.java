package org.proactiverobotics.sim2d.map;

import java.nio.file.Path;

/**
 * A map that cannot be used: a file missing or unreadable, a wrong magic number, a value out of range, a
 * size that disagrees with its header. The message names the file and the problem in one line.
 */
public final class MapException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final transient Path file;
    private final String problem;

    /**
     * @param file    the file at fault
     * @param problem what is wrong with it, in a few words
     */
    public MapException(Path file, String problem) {
        super(file + ": " + problem);
        this.file = file;
        this.problem = problem;
    }

    /** @return the file at fault */
    public Path file() {
        return file;
    }

    /** @return what is wrong with it, without the file's name */
    public String problem() {
        return problem;
    }
}
