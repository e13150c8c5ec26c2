package org.proactiverobotics.app;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.proactiverobotics.engine.robot.PluginException;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.robot.StrategyException;
import picocli.CommandLine.Option;

/**
 * The options that choose what the engine runs, shared by {@code run} and {@code engine} (a
 * picocli mixin): plug-in scenarios and the strategy, by name or from a file. Checked together,
 * before anything is written: a strategy must name loaded scenarios.
 */
public final class ScenarioOptions {

    /** The engine's start order as the help texts state it (an annotation needs a constant; StartOrderTest checks it). */
    static final String START_ORDER = RobotEngine.ORDER_TEXT;

    @Option(names = "--scenarios", paramLabel = "PATH", split = ",",
            description = "Scenario plug-ins: jars, or folders of jars, listing their scenarios in"
                    + " META-INF/services/org.proactiverobotics.engine.Scenario. Start order: " + ScenarioOptions.START_ORDER
                    + " (the plug-ins in the order given: the collision monitor vets their commands too).")
    private List<Path> scenarios = List.of();

    @Option(names = "--strategy", paramLabel = "NAME", completionCandidates = RunCommand.StrategyNames.class,
            description = "A bundled strategy (PriorityArray): ${COMPLETION-CANDIDATES}. Default: "
                    + Strategy.SAFETY_FIRST + ".")
    private String strategy;

    @Option(names = "--strategy-file", paramLabel = "FILE",
            description = "A strategy file: {\"name\": ..., \"priorities\": {\"<scenario>\": <int>, ...},"
                    + " \"timeoutsMs\": {\"<scenario>\": <ms>}}; a higher number is a higher priority.")
    private Path strategyFile;

    /**
     * What the engine runs with, checked.
     *
     * @param plugins  the loaded plug-ins
     * @param strategy the strategy, checked against the scenarios that suggest
     * @param unlisted scenarios that suggest but that the strategy leaves out (they rank below every listed one)
     */
    public record Choice(ScenarioPlugins plugins, Strategy strategy, List<String> unlisted) {

        /** @return the warning to print when the strategy leaves scenarios out, or null */
        public String unlistedWarning() {
            return unlisted.isEmpty() ? null : "strategy " + strategy.name() + " leaves out " + String.join(", ", unlisted)
                    + ": ranked below every scenario it lists";
        }
    }

    /**
     * Loads the plug-ins and the strategy.
     *
     * @param mayShareWorld whether the engine may run among other robots (a world with several, or an
     *                      engine process, which learns it from each robot's body): the strategy may
     *                      then name the traffic scenario, Yield, and one that does not gets it ranked
     *                      as {@link Strategy#forSharedWorld()} ranks it
     * @return the choice
     * @throws IllegalArgumentException ({@link PluginException}, {@link StrategyException}) naming the
     *                                  path, the file, the scenario or the key: bad input
     */
    public Choice load(boolean mayShareWorld) {
        if (strategy != null && strategyFile != null) {
            throw new StrategyException("give --strategy or --strategy-file, not both");
        }
        ScenarioPlugins plugins = ScenarioPlugins.load(scenarios, RobotEngine.builtInScenarios());
        Strategy chosen = strategyFile != null ? Strategy.read(strategyFile)
                : Strategy.named(strategy != null ? strategy : Strategy.SAFETY_FIRST);
        Map<String, Integer> slots = RobotEngine.freshSlots(plugins, mayShareWorld);
        try {
            chosen.check(slots);
        } catch (StrategyException e) {
            throw strategyFile == null ? e : new StrategyException("strategy file " + strategyFile + ": " + e.getMessage());
        }
        return new Choice(plugins, chosen, (mayShareWorld ? chosen.forSharedWorld() : chosen).unlisted(slots));
    }
}
