package org.proactiverobotics.app;

import com.zaxxer.hikari.HikariDataSource;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.proactiverobotics.app.deploy.DatabaseProblem;
import org.proactiverobotics.app.deploy.DatabaseWait;
import org.proactiverobotics.app.deploy.DbOptions;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.robot.StrategyException;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.StrategyTable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code strategy}: shows, and with {@code --set} changes, the PriorityArray of a robot's
 * mission from a process of its own (the paper's strategy change during execution). The
 * engine reads the strategy every iteration: a change holds from its next one. Run it as the
 * engine's user (the strategy is the engine's table).
 */
@Command(name = "strategy",
        mixinStandardHelpOptions = true,
        description = {"Shows the strategy (PriorityArray) of a robot's mission; --set NAME or --set-file FILE changes it while"
                + " the engine runs.",
                "Run it as the engine's database user. Exit codes: 0 done, 2 bad input (unknown strategy, bad strategy file,"
                + " a scenario the engine has not loaded), 3 database not usable."})
public final class StrategyCommand implements Callable<Integer> {

    @Mixin
    private DbOptions db;

    @Option(names = "--robot-id", paramLabel = "N", defaultValue = "1", description = "The robot. Default: ${DEFAULT-VALUE}.")
    private int robotId;

    @Option(names = "--set", paramLabel = "NAME", completionCandidates = RunCommand.StrategyNames.class,
            description = "Change the strategy to this one: ${COMPLETION-CANDIDATES}.")
    private String set;

    @Option(names = "--set-file", paramLabel = "FILE",
            description = "Change the strategy to this strategy file's: {\"name\": ..., \"priorities\": {\"<scenario>\": <int>},"
                    + " \"timeoutsMs\": {...}}. It may name only scenarios the robot's engine has loaded.")
    private Path setFile;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        String problem = db.problem();
        Strategy wanted = null;
        if (problem == null && set != null && setFile != null) {
            problem = "give --set or --set-file, not both";
        }
        if (problem == null && (set != null || setFile != null)) {
            try {
                wanted = setFile != null ? Strategy.read(setFile) : Strategy.named(set);
            } catch (StrategyException e) {
                problem = e.getMessage();
            }
        }
        if (problem != null) {
            err.println(problem);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        try {
            DatabaseWait.await(db, "strategy", () -> false);
        } catch (DatabaseWait.Unreachable e) {
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        try (HikariDataSource pool = Databases.pool(db.url(), db.user(), db.password())) {
            JdbcRobotTables tables = new JdbcRobotTables(pool, robotId);
            if (wanted != null) {
                List<StrategyTable.Entry> before = tables.read();
                Map<String, Integer> slots = slots(before);
                List<StrategyTable.Entry> rows;
                try {
                    rows = wanted.rows(slots);
                } catch (StrategyException e) {
                    err.println((setFile != null ? "strategy file " + setFile + ": " : "") + e.getMessage()
                            + (before.isEmpty() ? " (the robot's engine has not written its strategy yet: these are the"
                            + " built-in scenarios)" : ""));
                    err.flush();
                    return Main.EXIT_BAD_INPUT;
                }
                tables.write(rows);
                List<String> unlisted = wanted.unlisted(slots);
                if (!unlisted.isEmpty()) {
                    err.println("strategy " + wanted.name() + " leaves out " + String.join(", ", unlisted)
                            + ": ranked below every scenario it lists");
                    err.flush();
                }
                out.printf(Locale.ROOT, "robot %d: strategy %s -> %s (the engine obeys it from its next iteration)%n",
                        robotId, name(before), wanted.name());
            }
            print(out, tables.read());
            out.flush();
            return 0;
        } catch (RuntimeException e) {
            err.println(DatabaseProblem.of(e, db.url(), "strategy").message());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
    }

    /** The slots the engine gave, as its strategy rows show them; before it wrote any, the built-in ones. */
    private static Map<String, Integer> slots(List<StrategyTable.Entry> rows) {
        if (rows.isEmpty()) {
            return RobotEngine.freshSlots(ScenarioPlugins.none());
        }
        Map<String, Integer> slots = new LinkedHashMap<>();
        rows.forEach(e -> slots.put(e.scenario(), e.slot()));
        return slots;
    }

    private void print(PrintWriter out, List<StrategyTable.Entry> entries) {
        if (entries.isEmpty()) {
            out.printf(Locale.ROOT, "robot %d: no strategy yet (the engine writes its --strategy when it first serves the robot)%n",
                    robotId);
            return;
        }
        out.printf(Locale.ROOT, "robot %d: strategy %s (PriorityArray, highest priority first)%n", robotId, name(entries));
        out.printf(Locale.ROOT, "  %-8s  %-4s  %s%n", "priority", "slot", "scenario");
        entries.stream().sorted(Comparator.comparingInt(StrategyTable.Entry::priority).reversed())
                .forEach(e -> out.printf(Locale.ROOT, "  %-8d  %-4d  %s%n", e.priority(), e.slot(), e.scenario()));
    }

    private static String name(List<StrategyTable.Entry> entries) {
        return entries.isEmpty() ? "(none)" : entries.stream().map(StrategyTable.Entry::name).distinct()
                .reduce((a, b) -> a + "+" + b).orElse("(none)");
    }
}
