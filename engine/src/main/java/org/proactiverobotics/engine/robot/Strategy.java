package org.proactiverobotics.engine.robot;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;
import com.google.gson.JsonPrimitive;
import com.google.gson.Strictness;
import com.google.gson.stream.JsonReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * A strategy as data: a priority per scenario (higher is read first) and, optionally, a
 * suggestion time-out per scenario (simulated milliseconds, twist_mux style; 0 = one iteration).
 * It names scenarios, never slots: {@link #rows} turns it into the PriorityArray of the slots
 * the engine gave. A loaded scenario the strategy leaves out ranks below every listed one.
 *
 * <p>A strategy file is JSON:
 * <pre>{@code
 * {"name": "careful", "priorities": {"ObstacleAvoidance": 3, "SpeedGovernor": 2, "ReachDestination": 1},
 *  "timeoutsMs": {"SpeedGovernor": 500}}
 * }</pre>
 * The bundled named strategies ({@link #names()}) are such files, in this package's resources.
 *
 * @param name       the strategy's name (letters, digits, {@code - _ .}, at most 64 characters)
 * @param priorities priority by scenario name, in the file's order
 * @param timeoutsMs suggestion time-out by scenario name, simulated milliseconds
 */
public record Strategy(String name, Map<String, Integer> priorities, Map<String, Long> timeoutsMs) {

    /** The default: obstacle avoidance over the battery over the destination. */
    public static final String SAFETY_FIRST = "safety-first";
    /** The destination over avoidance over the battery: a reckless robot, for comparison. */
    public static final String DESTINATION_FIRST = "destination-first";
    /** The battery over avoidance over the destination. */
    public static final String BATTERY_FIRST = "battery-first";

    private static final List<String> NAMES = List.of(SAFETY_FIRST, DESTINATION_FIRST, BATTERY_FIRST);
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_.-]{1,64}");
    private static final Set<String> KEYS = Set.of("name", "priorities", "timeoutsMs");

    /** Checks and copies. */
    public Strategy {
        if (name == null || !NAME.matcher(name).matches()) {
            throw new StrategyException("strategy name '" + name + "': use 1 to 64 letters, digits, '-', '_' or '.'");
        }
        priorities = Collections.unmodifiableMap(new LinkedHashMap<>(priorities));
        timeoutsMs = Collections.unmodifiableMap(new LinkedHashMap<>(timeoutsMs));
        timeoutsMs.forEach((scenario, ms) -> {
            if (ms < 0) {
                throw new StrategyException("strategy " + name + ": timeoutsMs." + scenario + " must be >= 0: " + ms);
            }
        });
    }

    /**
     * This strategy for a world shared with other robots: the traffic scenario (Yield) ranked
     * right below ObstacleAvoidance, every other rank kept in its order (the priorities doubled to
     * make room), so the collision monitor still vets its backing off and it outranks what ranked
     * below the monitor. A strategy that lists Yield, or does not list ObstacleAvoidance, is
     * returned as it is. {@code safety-first} becomes ObstacleAvoidance 6, Yield 5, BatteryMonitor
     * 4, ReachDestination 2.
     *
     * @return the strategy for a shared world, of the same name
     */
    public Strategy forSharedWorld() {
        String yield = "Yield";
        String monitor = "ObstacleAvoidance";
        if (priorities.containsKey(yield) || !priorities.containsKey(monitor)) {
            return this;
        }
        Map<String, Integer> ranked = new LinkedHashMap<>();
        priorities.forEach((scenario, p) -> {
            ranked.put(scenario, 2 * p);
            if (scenario.equals(monitor)) {
                ranked.put(yield, 2 * p - 1);
            }
        });
        return new Strategy(name, ranked, timeoutsMs);
    }

    /** @return the bundled strategies' names, the default first */
    public static List<String> names() {
        return NAMES;
    }

    /**
     * @param name one of {@link #names()}
     * @return the bundled strategy
     * @throws StrategyException naming the known strategies when there is none of that name
     */
    public static Strategy named(String name) {
        String known = NAMES.stream().filter(n -> n.equalsIgnoreCase(name)).findFirst()
                .orElseThrow(() -> new StrategyException("unknown strategy '" + name + "'; known: " + String.join(", ", NAMES)));
        String resource = "strategies/" + known + ".json";
        try (InputStream in = Strategy.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("bundled strategy " + resource + " is missing from the engine jar");
            }
            return parse(new String(in.readAllBytes(), StandardCharsets.UTF_8), resource);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Reads a strategy file.
     *
     * @param file the JSON file
     * @return the strategy; its name defaults to the file's name without {@code .json}
     * @throws StrategyException naming the file and the key when the file is missing, not JSON,
     *                           or has an unknown key, a priority that is not an integer or a
     *                           time-out that is not a non-negative integer
     */
    public static Strategy read(Path file) {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new StrategyException("strategy file " + file + ": cannot be read: " + e.getMessage());
        }
        return parse(text, file.toString());
    }

    /**
     * @param json   the strategy as JSON
     * @param source where it came from, for messages (a file name)
     * @return the strategy
     * @throws StrategyException naming the source and the key
     */
    public static Strategy parse(String json, String source) {
        JsonElement root;
        try {
            JsonReader reader = new JsonReader(new StringReader(json));
            reader.setStrictness(Strictness.STRICT);
            root = JsonParser.parseReader(reader);
        } catch (JsonParseException | IllegalStateException e) {
            throw new StrategyException("strategy file " + source + ": not valid JSON: " + rootMessage(e));
        }
        if (!root.isJsonObject()) {
            throw new StrategyException("strategy file " + source + ": must be a JSON object {\"name\": ..., \"priorities\": {...}}");
        }
        JsonObject o = root.getAsJsonObject();
        for (String key : o.keySet()) {
            if (!KEYS.contains(key)) {
                throw new StrategyException("strategy file " + source + ": unknown key '" + key + "' (known: name, priorities, timeoutsMs)");
            }
        }
        String name = defaultName(source);
        if (o.has("name")) {
            JsonElement n = o.get("name");
            if (!n.isJsonPrimitive() || !n.getAsJsonPrimitive().isString()) {
                throw new StrategyException("strategy file " + source + ": name must be a string");
            }
            name = n.getAsString();
        }
        if (!o.has("priorities") || !o.get("priorities").isJsonObject() || o.getAsJsonObject("priorities").isEmpty()) {
            throw new StrategyException("strategy file " + source + ": priorities must be an object with at least one"
                    + " scenario, e.g. {\"ObstacleAvoidance\": 3, \"ReachDestination\": 1}");
        }
        Map<String, Integer> priorities = new LinkedHashMap<>();
        for (Map.Entry<String, JsonElement> e : o.getAsJsonObject("priorities").entrySet()) {
            long value = integer(e.getValue(), source, "priorities." + e.getKey(), Integer.MIN_VALUE + 1L, Integer.MAX_VALUE);
            priorities.put(e.getKey(), (int) value);
        }
        Map<String, Long> timeouts = new LinkedHashMap<>();
        if (o.has("timeoutsMs")) {
            if (!o.get("timeoutsMs").isJsonObject()) {
                throw new StrategyException("strategy file " + source + ": timeoutsMs must be an object {\"<scenario>\": <ms>}");
            }
            for (Map.Entry<String, JsonElement> e : o.getAsJsonObject("timeoutsMs").entrySet()) {
                timeouts.put(e.getKey(), integer(e.getValue(), source, "timeoutsMs." + e.getKey(), 0, Long.MAX_VALUE));
            }
        }
        try {
            return new Strategy(name, priorities, timeouts);
        } catch (StrategyException e) {
            throw new StrategyException("strategy file " + source + ": " + e.getMessage());
        }
    }

    /**
     * The strategy now in a robot's strategy table.
     *
     * @param rows the table's rows
     * @return the strategy they hold (named after their name column)
     */
    public static Strategy of(List<StrategyTable.Entry> rows) {
        Map<String, Integer> priorities = new LinkedHashMap<>();
        Map<String, Long> timeouts = new LinkedHashMap<>();
        for (StrategyTable.Entry e : rows) {
            priorities.put(e.scenario(), e.priority());
            if (e.timeoutMs() > 0) {
                timeouts.put(e.scenario(), e.timeoutMs());
            }
        }
        String name = rows.stream().map(StrategyTable.Entry::name).distinct().reduce((a, b) -> a + "+" + b).orElse("none");
        return new Strategy(name.length() > 64 ? name.substring(0, 64) : name, priorities, timeouts);
    }

    /**
     * Checks the strategy against the scenarios that suggest.
     *
     * @param slots each suggesting scenario's CommandArray slot
     * @throws StrategyException naming a scenario the strategy lists that has no slot, and the loaded ones
     */
    public void check(Map<String, Integer> slots) {
        for (String scenario : concat(priorities.keySet(), timeoutsMs.keySet())) {
            if (!slots.containsKey(scenario)) {
                throw new StrategyException("strategy " + name + " names scenario '" + scenario
                        + "', which is not loaded or does not suggest; scenarios that suggest: "
                        + String.join(", ", slots.keySet()));
            }
        }
    }

    /**
     * @param slots each suggesting scenario's slot
     * @return the scenarios that suggest but that this strategy leaves out (they rank below every listed one)
     */
    public List<String> unlisted(Map<String, Integer> slots) {
        List<String> left = new ArrayList<>();
        for (String scenario : slots.keySet()) {
            if (!priorities.containsKey(scenario)) {
                left.add(scenario);
            }
        }
        return left;
    }

    /**
     * The strategy table's rows: one per slot, in slot order; a scenario the strategy leaves out
     * gets a priority below every listed one (ties keep slot order).
     *
     * @param slots each suggesting scenario's CommandArray slot, as the engine gave them
     * @return the rows
     * @throws StrategyException when the strategy names a scenario without a slot
     */
    public List<StrategyTable.Entry> rows(Map<String, Integer> slots) {
        check(slots);
        int below = priorities.values().stream().mapToInt(Integer::intValue).min().orElse(1) - 1;
        List<StrategyTable.Entry> rows = new ArrayList<>(slots.size());
        slots.entrySet().stream().sorted(Map.Entry.comparingByValue()).forEach(e -> rows.add(new StrategyTable.Entry(
                e.getValue(), e.getKey(), priorities.getOrDefault(e.getKey(), below), name,
                timeoutsMs.getOrDefault(e.getKey(), 0L))));
        return List.copyOf(rows);
    }

    private static long integer(JsonElement value, String source, String key, long min, long max) {
        String problem = null;
        if (!value.isJsonPrimitive() || !((JsonPrimitive) value).isNumber()) {
            problem = "must be an integer, not " + value;
        } else {
            BigDecimal d = value.getAsBigDecimal();
            if (d.stripTrailingZeros().scale() > 0) {
                problem = "must be an integer, not " + value;
            } else if (d.compareTo(BigDecimal.valueOf(min)) < 0 || d.compareTo(BigDecimal.valueOf(max)) > 0) {
                problem = "must be between " + min + " and " + max + ", not " + value;
            } else {
                return d.longValueExact();
            }
        }
        throw new StrategyException("strategy file " + source + ": " + key + " " + problem);
    }

    private static String defaultName(String source) {
        String file = Path.of(source).getFileName().toString();
        String stem = file.endsWith(".json") ? file.substring(0, file.length() - 5) : file;
        String cleaned = stem.replaceAll("[^A-Za-z0-9_.-]", "_");
        return cleaned.isEmpty() ? "strategy" : cleaned.substring(0, Math.min(64, cleaned.length()));
    }

    private static List<String> concat(Collection<String> a, Collection<String> b) {
        List<String> all = new ArrayList<>(a);
        b.stream().filter(s -> !a.contains(s)).forEach(all::add);
        return all;
    }

    /** Where the JSON broke, in Gson's words without its advice and web link ("... at line 1 column 9 path $"). */
    private static String rootMessage(Throwable e) {
        Throwable t = e;
        while (t.getCause() != null) {
            t = t.getCause();
        }
        String text = String.valueOf(t.getMessage());
        Matcher where = Pattern.compile("line \\d+ column \\d+").matcher(text);
        return where.find() ? "malformed at " + where.group() : text.lines().findFirst().orElse(text);
    }
}
