package org.proactiverobotics.sim2d;

import java.util.List;

/**
 * A world file was refused. Carries every problem found, each starting with the key path it concerns
 * (for instance {@code checkpoints[2].x: expected a number, got a string}).
 */
public final class WorldValidationException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final String source;
    private final List<String> problems;

    /**
     * @param source   what was read (a file name, a resource, {@code <string>})
     * @param problems every problem found, at least one
     */
    public WorldValidationException(String source, List<String> problems) {
        super(message(source, problems));
        this.source = source;
        this.problems = List.copyOf(problems);
    }

    private static String message(String source, List<String> problems) {
        StringBuilder sb = new StringBuilder("invalid world file ").append(source).append(": ")
                .append(problems.size()).append(problems.size() == 1 ? " problem" : " problems");
        for (String p : problems) {
            sb.append(System.lineSeparator()).append("  ").append(p);
        }
        return sb.toString();
    }

    /**
     * @return what the command line prints: one line {@code SOURCE: invalid world file: PROBLEM} for
     *         one problem; for several, a header {@code SOURCE: invalid world file, N problems:} and
     *         one line per problem
     */
    public String report() {
        if (problems.size() == 1) {
            return source + ": invalid world file: " + problems.get(0);
        }
        return source + ": invalid world file, " + problems.size() + " problems:" + System.lineSeparator()
                + String.join(System.lineSeparator(), problems);
    }

    /** @return what was read (a file name, a resource, {@code <string>}) */
    public String source() {
        return source;
    }

    /** @return every problem found, in file order, each starting with its key path */
    public List<String> problems() {
        return problems;
    }
}
