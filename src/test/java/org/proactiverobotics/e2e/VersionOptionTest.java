package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.Main;
import picocli.CommandLine;

/** {@code -V/--version}, which --help advertises on every command, prints the version on every command. */
class VersionOptionTest extends CommandLineTest {

    @Test
    void everyCommandThatOffersVersionPrintsIt() {
        assertThat(run("--version")).isZero();
        String version = out.toString().strip();
        assertThat(version).startsWith("proactive-robotics ");

        List<List<String>> paths = new ArrayList<>();
        collect(Main.commandLine(), new ArrayList<>(), paths);
        assertThat(paths).as("commands offering -V").hasSizeGreaterThanOrEqualTo(9);
        for (List<String> path : paths) {
            for (String option : List.of("-V", "--version")) {
                out.getBuffer().setLength(0);
                List<String> args = new ArrayList<>(path);
                args.add(option);
                assertThat(run(args.toArray(String[]::new))).as(String.join(" ", args)).isZero();
                assertThat(out.toString().strip()).as(String.join(" ", args)).isEqualTo(version);
            }
        }
    }

    /** Every subcommand path, at any depth, whose command has a -V option. */
    private static void collect(CommandLine cl, List<String> path, List<List<String>> into) {
        for (var entry : cl.getSubcommands().entrySet()) {
            List<String> sub = new ArrayList<>(path);
            sub.add(entry.getKey());
            if (entry.getValue().getCommandSpec().findOption("-V") != null) {
                into.add(sub);
            }
            collect(entry.getValue(), sub, into);
        }
    }
}
