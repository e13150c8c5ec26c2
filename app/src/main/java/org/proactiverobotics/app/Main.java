package org.proactiverobotics.app;

import java.io.PrintWriter;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code proactive} command line: one jar, one subcommand per job (docs/command-line.md).
 * Exit codes: 0 success, 1 mission failed, 2 bad input, 3 infrastructure failure.
 */
@Command(name = "proactive",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = "Proactive Engine driving a simulated robot through a shared SQL database.",
        subcommands = {
                CommandLine.HelpCommand.class,
                ValidateCommand.class,
                RunCommand.class,
                SweepCommand.class,
                GenerateCommand.class,
                ImportMapCommand.class,
                WorldsCommand.class,
                EngineCommand.class,
                RobotCommand.class,
                StrategyCommand.class,
                DbCommand.class,
                WatchCommand.class,
                McapCheckCommand.class,
        })
public final class Main implements Runnable {

    /** Exit code: the mission failed (time limit, battery flat, ...). */
    public static final int EXIT_MISSION_FAILED = 1;
    /** Exit code: bad input (usage, invalid world or option). */
    public static final int EXIT_BAD_INPUT = 2;
    /** Exit code: infrastructure failure (database unreachable, ...). */
    public static final int EXIT_INFRASTRUCTURE = 3;

    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    public static void main(String[] args) {
        System.exit(commandLine().execute(args));
    }

    /** @return the configured command line, for main and for tests */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new Main());
        giveEverySubcommandTheVersion(cl);
        cl.setExitCodeExceptionMapper(e -> e instanceof CommandLine.ParameterException ? EXIT_BAD_INPUT : EXIT_INFRASTRUCTURE);
        cl.setParameterExceptionHandler(Main::usageError);
        return cl;
    }

    /**
     * A usage error in a few lines, not the whole usage: what is wrong, the option or command a
     * letter or two away that was likely meant (else picocli's own guess), and where the options
     * are listed.
     */
    private static int usageError(CommandLine.ParameterException e, String[] args) {
        CommandLine cl = e.getCommandLine();
        CommandLine.Model.CommandSpec spec = cl.getCommandSpec();
        PrintWriter err = cl.getErr();
        String message = e.getMessage();
        List<String> suggestions = List.of();
        if (e instanceof CommandLine.UnmatchedArgumentException u && !u.getUnmatched().isEmpty()) {
            String typed = u.getUnmatched().get(0);
            if (u.isUnknownOption()) {
                message = "unknown option " + typed;
                suggestions = Suggestions.closest(typed, spec.optionsMap().keySet());
            } else if (!spec.subcommands().isEmpty()) {
                message = "unknown command " + typed;
                suggestions = Suggestions.closest(typed, spec.subcommands().keySet());
            } else {
                message = "unexpected argument " + typed
                        + (spec.positionalParameters().isEmpty() ? " (" + spec.name() + " takes options only)" : "");
            }
            if (suggestions.isEmpty()) {
                suggestions = u.getSuggestions();
            }
        }
        err.println(message);
        if (!suggestions.isEmpty()) {
            err.println("Did you mean: " + String.join(" or ", suggestions) + "?");
        }
        err.println("See '" + spec.qualifiedName() + " --help'.");
        err.flush();
        return EXIT_BAD_INPUT;
    }

    /** Every subcommand offers -V/--version (mixinStandardHelpOptions): without a provider it would print nothing. */
    private static void giveEverySubcommandTheVersion(CommandLine cl) {
        for (CommandLine sub : cl.getSubcommands().values()) {
            if (sub.getCommandSpec().versionProvider() == null) {
                sub.getCommandSpec().versionProvider(new Version());
            }
            giveEverySubcommandTheVersion(sub);
        }
    }

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "Missing subcommand");
    }

    /** Reads the version from the jar's manifest. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String version = Main.class.getPackage().getImplementationVersion();
            return new String[] {"proactive-robotics " + (version == null ? "(development build)" : version)};
        }
    }
}
