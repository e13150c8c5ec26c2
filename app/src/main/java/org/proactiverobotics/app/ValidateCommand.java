package org.proactiverobotics.app;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.WorldValidationException;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code validate --world FILE} (docs/command-line.md): checks a world file against its format
 * (docs/world-file.md). Exit 0 with a one-line summary on standard output when valid; exit 2 with every problem, one
 * per line, on standard error when not.
 */
@Command(name = "validate",
        mixinStandardHelpOptions = true,
        description = {"Checks a world file (its format: docs/world-file.md) and lists every problem found.",
                "Exit codes: 0 valid, 2 invalid or unreadable (problems on standard error)."})
public final class ValidateCommand implements Callable<Integer> {

    @Option(names = "--world", required = true, paramLabel = "FILE", description = "The world file (JSON) to check.")
    private Path world;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        try {
            WorldSpec w = WorldFiles.load(world);
            PrintWriter out = spec.commandLine().getOut();
            out.println(summary(w));
            out.flush();
            return 0;
        } catch (WorldValidationException e) {
            PrintWriter err = spec.commandLine().getErr();
            int n = e.problems().size();
            err.println(world + ": invalid world file, " + n + (n == 1 ? " problem:" : " problems:"));
            e.problems().forEach(err::println);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
    }

    /** @return e.g. {@code reference-arena: valid (3 obstacles, 4 checkpoints, arena radius 5.0 m)} */
    static String summary(WorldSpec w) {
        int obstacles = w.obstacles().size();
        int checkpoints = w.checkpoints().size();
        return String.format(Locale.ROOT, "%s: valid (%d %s, %d %s, arena radius %s m)", w.name(),
                obstacles, obstacles == 1 ? "obstacle" : "obstacles",
                checkpoints, checkpoints == 1 ? "checkpoint" : "checkpoints", w.arena().radiusM());
    }
}
