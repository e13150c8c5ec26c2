package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.Main;
import org.proactiverobotics.engine.robot.RobotEngine;
import picocli.CommandLine;

/**
 * The order the engine starts its scenarios in is stated the same way everywhere a user reads it
 * (README.md, docs/*.md, every command's {@code --help}) as the engine really uses it: a statement
 * of the whole order is the engine's own phrase ({@link RobotEngine#startOrderPhrase()}), an arrow
 * chain of scenarios keeps the engine's order, and no sentence has the plug-ins start after the
 * collision monitor (it vets their commands, so it starts after them).
 */
class StartOrderTest {

    /** The engine's order, the plug-ins standing as {@value RobotEngine#PLUGINS}. */
    private static final List<String> ORDER = RobotEngine.startOrder(List.of(RobotEngine.PLUGINS));
    private static final String OBSTACLE_AVOIDANCE = "ObstacleAvoidance";
    /** How a text names the plug-in scenarios. */
    private static final String PLUGIN_WORDS = "(?:plug-?ins?|--scenarios|their scenarios|your scenarios?)";

    /** Plug-ins said to start after every built-in scenario that suggests: ObstacleAvoidance suggests. */
    private static final Pattern AFTER_THE_SUGGESTING_ONES =
            Pattern.compile("after (?:all |every |each )?(?:of )?the built-in (?:scenarios|ones)(?: that suggest)", Pattern.CASE_INSENSITIVE);
    /** ObstacleAvoidance said to start before the plug-ins. */
    private static final Pattern COLLISION_MONITOR_BEFORE_PLUGINS = Pattern.compile(OBSTACLE_AVOIDANCE
            + "(?:(?!" + PLUGIN_WORDS + ")[^.]){0,60}\\b(?:before|then)\\b(?:(?!" + OBSTACLE_AVOIDANCE + ")[^.]){0,60}?"
            + PLUGIN_WORDS, Pattern.CASE_INSENSITIVE);
    /** ObstacleAvoidance listed just before the plug-ins: "..., ObstacleAvoidance, the plug-ins, ...". */
    private static final Pattern LISTED_BEFORE_PLUGINS = Pattern.compile(OBSTACLE_AVOIDANCE
            + "\\s*(?:,|;|,? and|,? then)\\s+(?:then\\s+)?(?:the\\s+|any\\s+)?" + PLUGIN_WORDS, Pattern.CASE_INSENSITIVE);
    private static final Pattern PLUGIN = Pattern.compile(PLUGIN_WORDS, Pattern.CASE_INSENSITIVE);
    private static final Pattern AFTER = Pattern.compile("\\bafter\\b", Pattern.CASE_INSENSITIVE);
    private static final Pattern BEFORE = Pattern.compile("\\bbefore\\b", Pattern.CASE_INSENSITIVE);

    @Test
    void theEnginesPhraseIsTheBuildersOrder() {
        assertThat(RobotEngine.startOrderPhrase()).isEqualTo(String.join(" → ", ORDER))
                .isEqualTo("DataAcquisition → Localisation → Mapping → BatteryMonitor → ReachDestination → plug-ins → ObstacleAvoidance"
                        + " → FailSafe → DecisionMaking");
    }

    @Test
    void everyHelpTextOfACommandThatTakesPluginsStatesTheEnginesOrder() {
        Map<String, String> helps = helpTexts();
        List<String> withPlugins = helps.entrySet().stream()
                .filter(e -> e.getValue().contains("--scenarios=")).map(Map.Entry::getKey).toList();
        assertThat(withPlugins).contains("proactive run", "proactive engine", "proactive sweep");
        for (String command : withPlugins) {
            assertThat(flat(helps.get(command))).as("%s --help", command).contains(RobotEngine.startOrderPhrase());
        }
    }

    @Test
    void noHelpTextReadmeOrDocStatesAnotherOrder() throws IOException {
        Map<String, String> texts = new LinkedHashMap<>();
        helpTexts().forEach((command, help) -> texts.put(command + " --help", help));
        Path root = Deployment.root();
        texts.put("README.md", Files.readString(root.resolve("README.md")));
        try (Stream<Path> docs = Files.list(root.resolve("docs"))) {
            for (Path doc : docs.filter(p -> p.toString().endsWith(".md")).sorted().toList()) {
                texts.put(root.relativize(doc).toString(), Files.readString(doc));
            }
        }
        List<String> wrong = new ArrayList<>();
        texts.forEach((where, text) -> sentences(text).forEach(s -> {
            String problem = disagreement(s);
            if (problem != null) {
                wrong.add(where + ": " + problem + ": \"" + s + "\"");
            }
        }));
        assertThat(wrong).as("statements of the start order that disagree with the engine's (%s)",
                RobotEngine.startOrderPhrase()).isEmpty();
        assertThat(flat(texts.get("docs/command-line.md"))).contains(RobotEngine.startOrderPhrase());
        assertThat(flat(texts.get("README.md"))).as("README.md states the start order").contains(RobotEngine.startOrderPhrase());
    }

    /** The checks catch what the manual and the help texts said before the order was stated once, and pass the truth. */
    @Test
    void theChecksTellAWrongOrderFromTheRightOne() {
        List<String> wrongs = List.of(
                "They start after the built-in scenarios that suggest, in the order given, before FailSafe and DecisionMaking.",
                "Scenarios of your own: jars built against the `engine` artifact, started after the built-in scenarios"
                        + " that suggest, each in the next CommandArray slot.",
                "started in the order 1 → Mapping → 4 → 2 → 3 → plug-ins (`--scenarios`) → FailSafe → 5; one wiring",
                "their scenarios start in the order given, after the built-in scenarios that suggest (DataAcquisition,"
                        + " Mapping, BatteryMonitor, ReachDestination, ObstacleAvoidance) and before FailSafe and DecisionMaking.",
                "The plug-ins start after ObstacleAvoidance.",
                "ObstacleAvoidance starts before the plug-ins.",
                "Start order: DataAcquisition, Mapping, BatteryMonitor, ReachDestination, ObstacleAvoidance, the plug-ins,"
                        + " FailSafe, DecisionMaking.",
                "DataAcquisition → Mapping → BatteryMonitor → ReachDestination → ObstacleAvoidance → plug-ins → FailSafe"
                        + " → DecisionMaking",
                "FailSafe → ObstacleAvoidance → DecisionMaking");
        for (String wrong : wrongs) {
            assertThat(disagreement(flat(wrong))).as(wrong).isNotNull();
        }
        List<String> rights = List.of(
                "Start order: DataAcquisition → Localisation → Mapping → BatteryMonitor → ReachDestination → plug-ins"
                        + " → ObstacleAvoidance → FailSafe → DecisionMaking (the plug-ins in the order given).",
                "Whatever your scenario suggests, ObstacleAvoidance vets it (it starts after the plug-ins) and drives the"
                        + " nearest arc that keeps clear instead.",
                "`--scenarios` in the order given, then ObstacleAvoidance (the collision monitor vets the command).",
                "FailSafe starts after the plug-ins and ObstacleAvoidance, before DecisionMaking.",
                "the paper's 1 → 4 → 2 → 3, Mapping after 1",
                "scenarios that suggest: ReachDestination, BatteryMonitor, ObstacleAvoidance, SpeedGovernor",
                "engine → database → robot");
        for (String right : rights) {
            assertThat(disagreement(flat(right))).as(right).isNull();
        }
    }

    /**
     * @param sentence one sentence, whitespace flattened
     * @return what is wrong with it as a statement of the start order, or null when it states none or the engine's
     */
    private static String disagreement(String sentence) {
        String chainProblem = chainDisagreement(sentence);
        if (chainProblem != null) {
            return chainProblem;
        }
        boolean whole = ORDER.stream().filter(n -> !n.equals(RobotEngine.PLUGINS)).allMatch(sentence::contains)
                && PLUGIN.matcher(sentence).find();
        if (whole && !sentence.contains(RobotEngine.startOrderPhrase())) {
            return "gives the whole order, but not as the engine's phrase";
        }
        if (AFTER_THE_SUGGESTING_ONES.matcher(sentence).find()) {
            return "has the plug-ins start after the built-in scenarios that suggest, ObstacleAvoidance among them";
        }
        if (COLLISION_MONITOR_BEFORE_PLUGINS.matcher(sentence).find() || LISTED_BEFORE_PLUGINS.matcher(sentence).find()) {
            return "puts ObstacleAvoidance before the plug-ins";
        }
        if (pluginsAfterTheCollisionMonitor(sentence)) {
            return "has the plug-ins start after ObstacleAvoidance";
        }
        return null;
    }

    /** "the plug-ins start ... after ... ObstacleAvoidance ..." (up to a "before"), the plug-ins being the subject. */
    private static boolean pluginsAfterTheCollisionMonitor(String sentence) {
        if (!sentence.toLowerCase(Locale.ROOT).contains("start")) {
            return false;
        }
        Matcher after = AFTER.matcher(sentence);
        while (after.find()) {
            String before = sentence.substring(0, after.start());
            String rest = sentence.substring(after.end());
            Matcher stop = BEFORE.matcher(rest);
            String afterWhat = stop.find() ? rest.substring(0, stop.start()) : rest;
            if (PLUGIN.matcher(before).find() && !PLUGIN.matcher(afterWhat).find() && afterWhat.contains(OBSTACLE_AVOIDANCE)) {
                return true;
            }
        }
        return false;
    }

    /**
     * An arrow chain (A → B → C) naming scenarios: with the plug-ins in it, it states the whole order
     * and must be the engine's phrase; without, the scenarios it names must come in the engine's order.
     */
    private static String chainDisagreement(String sentence) {
        String[] pieces = sentence.split("→", -1);
        if (pieces.length < 3) {
            return null;
        }
        List<String> named = new ArrayList<>();
        boolean plugins = false;
        for (int i = 0; i < pieces.length; i++) {
            String piece = pieces[i].replaceAll("\\([^)]*\\)|`", " ").strip();
            String[] words = piece.split("\\s+");
            // the first piece ends with the chain's first element; the last begins with its last one
            String element = i == 0 ? words[words.length - 1]
                    : i == pieces.length - 1 ? String.join(" ", List.of(words).subList(0, Math.min(2, words.length))) : piece;
            if (PLUGIN.matcher(element).find()) {
                plugins = true;
                named.add(RobotEngine.PLUGINS);
            }
            for (String name : ORDER) {
                if (!name.equals(RobotEngine.PLUGINS) && List.of(element.split("[^A-Za-z]+")).contains(name)) {
                    named.add(name);
                }
            }
        }
        if (plugins && !sentence.contains(RobotEngine.startOrderPhrase())) {
            return "gives the order with the plug-ins in an arrow chain, but not as the engine's phrase";
        }
        for (int i = 1; i < named.size(); i++) {
            if (ORDER.indexOf(named.get(i - 1)) > ORDER.indexOf(named.get(i))) {
                return "puts " + named.get(i - 1) + " before " + named.get(i);
            }
        }
        return null;
    }

    /** @return each command's and subcommand's help, by its name ("proactive sweep merge") */
    private static Map<String, String> helpTexts() {
        Map<String, String> helps = new LinkedHashMap<>();
        collect(Main.commandLine(), helps);
        return helps;
    }

    private static void collect(CommandLine cl, Map<String, String> helps) {
        helps.put(cl.getCommandSpec().qualifiedName(), cl.getUsageMessage(CommandLine.Help.Ansi.OFF));
        cl.getSubcommands().values().forEach(sub -> collect(sub, helps));
    }

    /** @return the text cut into sentences (of paragraphs, table cells, list items), whitespace (line wraps) flattened */
    private static List<String> sentences(String text) {
        List<String> sentences = new ArrayList<>();
        for (String paragraph : text.split("\\n\\s*\\n|\\||\\n\\s*[-*] ")) { // paragraphs, table cells, list items
            for (String sentence : flat(paragraph).split("(?<=[.!?])\\s+(?=[A-Z`\\[(])")) {
                if (!sentence.isBlank()) {
                    sentences.add(sentence);
                }
            }
        }
        return sentences;
    }

    private static String flat(String text) {
        return text.replaceAll("\\s+", " ").strip();
    }
}
