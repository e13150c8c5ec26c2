package org.proactiverobotics.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.proactiverobotics.app.sweep.SweepMerge;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code sweep merge}: joins the folders of a sharded sweep's slices into one results.csv and
 * summary.html (see {@link SweepMerge}); the missions' folders stay where their shards wrote them.
 */
@Command(name = "merge",
        mixinStandardHelpOptions = true,
        description = {"Joins the folders that 'sweep --shard I/N' wrote, one per slice, into one results.csv (rows in the"
                + " missions' order, as one unsharded sweep) and one summary page that links each mission's folder where"
                + " it is.",
                "Refuses, writing nothing, folders of different sweeps or cuts, a slice given twice or missing, and a"
                        + " mission with no row (a shard stopped or failed) or with two.",
                "Exit codes: 0 merged (whatever the missions' outcomes: see the counts), 2 the shards do not make one"
                        + " whole sweep, 3 a file could not be read or written."})
public final class SweepMergeCommand implements Callable<Integer> {

    @Parameters(paramLabel = "DIR", arity = "1..*", description = "The shards' folders (each with sweep.json and results.csv).")
    private List<Path> dirs = new ArrayList<>();

    @Option(names = "--out", paramLabel = "DIR",
            description = "Where results.csv and summary.html go. Default: the folder the shards' folders are in, when they"
                    + " share one.")
    private Path out;

    @Option(names = "--force", description = "Replace a results.csv or summary.html already in --out.")
    private boolean force;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter stdout = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        List<String> beforeMerge = spec.parent().commandLine().getParseResult().matchedOptions().stream()
                .map(o -> o.longestName()).toList();
        if (!beforeMerge.isEmpty()) { // they went to 'sweep', which does not run: say so rather than ignore them
            err.println("give sweep merge's options after 'merge' (" + String.join(", ", beforeMerge)
                    + " came before it): sweep merge [--out DIR] [--force] DIR...");
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        Path target = out != null ? out : commonParent();
        if (target == null) {
            err.println("the shards' folders are not in one folder: give --out DIR");
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        try {
            SweepMerge.Merged m = SweepMerge.merge(dirs, target, force);
            stdout.printf(Locale.ROOT, "Merged %s: %d of %s accomplished (%.1f s of missions' wall time in all)%n",
                    Plural.of(m.shards(), "shard"), m.accomplished(), Plural.of(m.missions(), "mission"), m.missionsWallTimeS());
            stdout.println("Results: " + target.resolve("results.csv"));
            stdout.println("Summary: " + target.resolve("summary.html"));
            stdout.flush();
            return 0;
        } catch (SweepMerge.Refused e) {
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        } catch (IOException e) {
            err.println("cannot merge into " + target + ": " + e);
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
    }

    private Path commonParent() {
        Path parent = null;
        for (Path d : dirs) {
            Path p = d.toAbsolutePath().normalize().getParent();
            if (p == null || (parent != null && !parent.equals(p))) {
                return null;
            }
            parent = p;
        }
        return parent;
    }
}
