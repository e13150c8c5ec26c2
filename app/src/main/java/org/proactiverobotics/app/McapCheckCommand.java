package org.proactiverobotics.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.proactiverobotics.mcap.McapCheck;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code mcap-check}: reads a run.mcap from end to end and says whether it is whole (its channels,
 * message counts and simulated time span) or, in one line, why not: cut short (a run killed before
 * it closed the file: where it ends and what can still be read) or not a valid MCAP file.
 */
@Command(name = "mcap-check",
        mixinStandardHelpOptions = true,
        description = {"Checks an MCAP file written with --mcap: every record, chunk CRC, index and the summary.",
                "Prints its channels and message counts; says so when the file is cut short or damaged.",
                "Exit codes: 0 whole, 2 incomplete, damaged, not MCAP or not readable."})
public final class McapCheckCommand implements Callable<Integer> {

    @Parameters(paramLabel = "FILE", description = "The file, e.g. runs/reference-arena-.../run.mcap.")
    private Path file;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (!Files.isRegularFile(file)) {
            err.println("no such file: " + file);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        McapCheck.Report r;
        try {
            r = McapCheck.check(file);
        } catch (IOException | OutOfMemoryError e) {
            err.println("cannot read " + file + ": " + e.getMessage());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        if (r.incomplete()) {
            err.printf(Locale.ROOT, "%s is incomplete: %s (cut at byte %d); %s readable%s%n", file, r.problem(),
                    r.cutAtByte(), Plural.of(r.messages(), "message"),
                    r.messages() == 0 ? "" : String.format(Locale.ROOT, ", up to %.3f s", r.endTimeNs() / 1e9));
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        if (!r.ok()) {
            err.println(file + " is not a valid MCAP file: " + r.problem());
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        out.printf(Locale.ROOT, "%s: whole, %s on %s in %s, %.3f s to %.3f s, %d bytes%n", file,
                Plural.of(r.messages(), "message"), Plural.of(r.channels().size(), "channel"), Plural.of(r.chunks(), "chunk"),
                r.startTimeNs() / 1e9, r.endTimeNs() / 1e9, r.sizeBytes());
        int width = r.channels().stream().mapToInt(c -> c.topic().length()).max().orElse(5);
        for (McapCheck.ChannelCount c : r.channels()) {
            out.printf(Locale.ROOT, "  %-" + width + "s  %-24s  %d%n", c.topic(), c.schemaName(), c.messages());
        }
        out.flush();
        return 0;
    }
}
