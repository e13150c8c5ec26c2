package org.proactiverobotics.app;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code worlds}: lists the worlds bundled in the jar, which {@code run}, {@code robot} and {@code validate}
 * accept by name ({@code --world low-battery}): name, checkpoints, obstacles and what each is for.
 */
@Command(name = "worlds",
        mixinStandardHelpOptions = true,
        description = {"Lists the worlds bundled in the jar: run, robot and validate take their names as --world NAME.",
                "Exit codes: 0."})
public final class WorldsCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        List<String> names = WorldFiles.bundledNames();
        int width = Math.max("NAME".length(), names.stream().mapToInt(String::length).max().orElse(0)
                + " (default)".length());
        String row = "%-" + width + "s  %11s  %9s  %s%n";
        out.printf(Locale.ROOT, row, "NAME", "CHECKPOINTS", "OBSTACLES", "WHAT IT IS FOR");
        for (String name : names) {
            WorldSpec world = WorldFiles.bundled(name);
            String label = name.equals(WorldFiles.DEFAULT_WORLD) ? name + " (default)" : name;
            out.printf(Locale.ROOT, row, label, world.checkpoints().size(), world.obstacles().size(),
                    WorldFiles.description(name));
        }
        out.flush();
        return 0;
    }
}
