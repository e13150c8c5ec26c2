package org.proactiverobotics.app;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.proactiverobotics.sim2d.WorldSpec;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code validate --world FILE|NAME} (docs/command-line.md): checks a world file against its format
 * (docs/world-file.md). Exit 0 with a one-line summary on standard output when valid (and a line per robot for a
 * world with several); exit 2 with every problem, one per line, on standard error when not.
 */
@Command(name = "validate",
        mixinStandardHelpOptions = true,
        description = {"Checks a world file (its format: docs/world-file.md) and lists every problem found.",
                "Exit codes: 0 valid, 2 invalid or unreadable (problems on standard error)."})
public final class ValidateCommand implements Callable<Integer> {

    @Option(names = "--world", required = true, paramLabel = "FILE|NAME",
            completionCandidates = WorldArgument.BundledNames.class,
            description = "The world to check: a JSON file, or the name of a bundled world (${COMPLETION-CANDIDATES}).")
    private String world;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        WorldSpec w = WorldArgument.load(world, spec.commandLine().getErr());
        if (w == null) {
            return Main.EXIT_BAD_INPUT;
        }
        PrintWriter out = spec.commandLine().getOut();
        out.println(summary(w));
        if (w.hasSeveralRobots()) {
            w.robots().forEach(r -> out.println(robotLine(r)));
        }
        out.flush();
        return 0;
    }

    /**
     * @return e.g. {@code reference-arena: valid (3 obstacles, 4 checkpoints, arena radius 5.0 m)}, or for a
     *         rectangle {@code ... arena 56.0 x 60.0 m centred on (12.0, -3.5))}; for several robots or stations
     *         {@code fleet-corridor: valid (2 robots, 2 obstacles, 2 checkpoints, 2 recharge stations, arena ...)}
     */
    static String summary(WorldSpec w) {
        WorldSpec.Arena a = w.arena();
        String arena = a.isCircle() ? String.format(Locale.ROOT, "arena radius %s m", a.radiusM())
                : String.format(Locale.ROOT, "arena %s x %s m centred on (%s, %s)", a.widthM(), a.heightM(), a.x(), a.y());
        if (!w.hasSeveralRobots() && w.rechargeStations().size() == 1) {
            return String.format(Locale.ROOT, "%s: valid (%s, %s, %s)", w.name(),
                    Plural.of(w.obstacles().size(), "obstacle"), Plural.of(w.checkpoints().size(), "checkpoint"), arena);
        }
        int checkpoints = w.robots().stream().mapToInt(r -> r.checkpoints().size()).sum();
        return String.format(Locale.ROOT, "%s: valid (%s, %s, %s, %s, %s)", w.name(), Plural.of(w.robots().size(), "robot"),
                Plural.of(w.obstacles().size(), "obstacle"), Plural.of(checkpoints, "checkpoint"),
                Plural.of(w.rechargeStations().size(), "recharge station"), arena);
    }

    /** @return e.g. {@code   robot 2: start (3.0, 0.5) heading 180.0°, radius 0.15 m, 2 checkpoints (-3.0, 0.5) (0.0, 3.0)} */
    static String robotLine(WorldSpec.RobotEntry entry) {
        WorldSpec.Robot r = entry.robot();
        StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "  robot %d: start (%s, %s) heading %s°, radius %s m, %s",
                entry.id(), r.x(), r.y(), r.headingDeg(), r.radiusM(), Plural.of(entry.checkpoints().size(), "checkpoint")));
        for (WorldSpec.Checkpoint c : entry.checkpoints()) {
            line.append(String.format(Locale.ROOT, " (%s, %s)", c.x(), c.y()));
        }
        return line.toString();
    }
}
