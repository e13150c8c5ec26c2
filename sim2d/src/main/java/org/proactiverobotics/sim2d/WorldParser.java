package org.proactiverobotics.sim2d;

import java.io.IOException;
import java.io.StringReader;
import java.math.BigDecimal;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonPrimitive;
import com.google.gson.Strictness;
import com.google.gson.stream.JsonReader;
import com.google.gson.stream.JsonToken;
import org.proactiverobotics.sim2d.map.BoxCover;
import org.proactiverobotics.sim2d.map.MapException;
import org.proactiverobotics.sim2d.map.MapFiles;
import org.proactiverobotics.sim2d.map.OccupancyGrid;

/**
 * Reads a world file's JSON into a {@link WorldSpec}, collecting every problem rather than stopping at the
 * first (docs/world-file.md). One instance per file.
 */
final class WorldParser {

    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_-]+");
    private static final Set<String> ROOT_KEYS = Set.of("name", "timeStepMs", "maxSimTimeS", "seed", "arena", "robot",
            "obstacles", "checkpoints", "checkpointRadiusM", "rechargeStation", "battery", "map", "robots", "rechargeStations");
    private static final Set<String> ARENA_KEYS = Set.of("radiusM", "widthM", "heightM", "x", "y");
    private static final Set<String> MAP_KEYS = Set.of("file", "cellM");
    private static final Set<String> ROBOT_KEYS = Set.of("x", "y", "headingDeg", "radiusM", "maxSpeedMps", "sensorRangeM",
            "sensorAnglesDeg");
    /** The most distance sensors a robot may carry (a laser scanner's rays, say). */
    static final int MAX_SENSORS = 360;
    /** A {@code robots} entry: every key {@code robot} takes, its id and its own checkpoints. */
    private static final Set<String> FLEET_ROBOT_KEYS = Set.of("id", "x", "y", "headingDeg", "radiusM", "maxSpeedMps",
            "sensorRangeM", "sensorAnglesDeg", "checkpoints");
    private static final Set<String> BOX_KEYS = Set.of("shape", "x", "y", "widthM", "heightM", "angleDeg");
    private static final Set<String> CIRCLE_KEYS = Set.of("shape", "x", "y", "radiusM");
    private static final Set<String> POINT_KEYS = Set.of("x", "y");
    private static final Set<String> STATION_KEYS = Set.of("x", "y", "radiusM");
    private static final Set<String> BATTERY_KEYS = Set.of("initial", "drainPerMeter", "rechargeTo", "rechargeRatePerS");

    /** What a number must satisfy beyond being finite. */
    private enum Bound { ANY, POSITIVE, NON_NEGATIVE, POSITIVE_PERCENT }

    private final List<String> problems = new ArrayList<>();
    /** Where a map's file name is resolved from: the world file's folder (the working directory for a string). */
    private final Path baseDir;
    /** The map named by the world, or null. */
    private Path mapFile;
    /** How many obstacles the file lists (the map's boxes follow them). */
    private int listedObstacles;

    /** @param baseDir the folder a map's file name is relative to: the world file's */
    WorldParser(Path baseDir) {
        this.baseDir = baseDir;
    }

    /**
     * @param json   the file's text
     * @param source what was read, for the exception's message
     * @return the validated world
     * @throws WorldValidationException listing every problem
     */
    WorldSpec parse(String json, String source) {
        JsonElement rootElement = readJson(json);
        if (rootElement == null) {
            throw new WorldValidationException(source, problems);
        }
        if (!rootElement.isJsonObject()) {
            problems.add("(root): expected a JSON object, got " + kind(rootElement));
            throw new WorldValidationException(source, problems);
        }
        JsonObject root = rootElement.getAsJsonObject();
        unknownKeys(root, "", ROOT_KEYS);

        String name = name(root);
        Integer timeStepMs = timeStep(root);
        Double maxSimTimeS = number(root, "", "maxSimTimeS", false, Bound.POSITIVE, WorldSpec.DEFAULT_MAX_SIM_TIME_S);
        Long seed = seed(root);
        OccupancyGrid map = map(root);
        WorldSpec.Arena arena = arena(root, map);
        boolean fleet = root.has("robots");
        List<WorldSpec.RobotEntry> fleetRobots = fleet ? robots(root) : null;
        WorldSpec.Robot robot = fleet ? null : robot(root, "robot");
        List<WorldSpec.Obstacle> obstacles = obstacles(root);
        if (obstacles != null) {
            listedObstacles = obstacles.size();
        }
        if (obstacles != null && map != null) {
            List<WorldSpec.Obstacle> all = new ArrayList<>(obstacles);
            all.addAll(BoxCover.boxes(map));
            obstacles = Collections.unmodifiableList(all);
        }
        List<WorldSpec.Checkpoint> checkpoints = fleet ? null : checkpoints(root, "");
        Double checkpointRadiusM = number(root, "", "checkpointRadiusM", false, Bound.POSITIVE,
                WorldSpec.DEFAULT_CHECKPOINT_RADIUS_M);
        List<WorldSpec.RechargeStation> stations = stations(root);
        WorldSpec.Battery battery = battery(root);

        if (arena != null && obstacles != null) {
            if (robot != null) {
                missionPlacement("robot", "", robot, checkpoints, arena, obstacles);
            }
            if (fleetRobots != null) {
                for (int i = 0; i < fleetRobots.size(); i++) {
                    WorldSpec.RobotEntry entry = fleetRobots.get(i);
                    if (entry != null) {
                        missionPlacement("robots[" + i + "]", "robots[" + i + "].", entry.robot(), entry.checkpoints(),
                                arena, obstacles);
                    }
                }
            }
            // a station must be where a robot's centre can be: checked for the widest robot, the one it fits worst
            WorldSpec.Robot widest = fleetRobots == null ? robot : widest(fleetRobots);
            if (stations != null && widest != null) {
                String key = root.has("rechargeStations") ? "rechargeStations[%d]" : "rechargeStation";
                for (int i = 0; i < stations.size(); i++) {
                    WorldSpec.RechargeStation st = stations.get(i);
                    if (st != null) {
                        placement(String.format(Locale.ROOT, key, i), "station", st.x(), st.y(), arena, widest, obstacles);
                    }
                }
            }
        }
        if (fleetRobots != null) {
            overlaps(fleetRobots);
        }
        if (!problems.isEmpty()) {
            throw new WorldValidationException(source, problems);
        }
        if (fleet) {
            return WorldSpec.fleet(name, timeStepMs, maxSimTimeS, seed, arena, fleetRobots, obstacles, checkpointRadiusM,
                    stations, battery);
        }
        return new WorldSpec(name, timeStepMs, maxSimTimeS, seed, arena, robot, obstacles, checkpoints,
                checkpointRadiusM, stations.get(0), battery, null, stations);
    }

    /** Checks a robot's start and each of its checkpoints: inside the arena and clear of every obstacle. */
    private void missionPlacement(String robotPath, String checkpointPrefix, WorldSpec.Robot robot,
                                  List<WorldSpec.Checkpoint> checkpoints, WorldSpec.Arena arena,
                                  List<WorldSpec.Obstacle> obstacles) {
        placement(robotPath, "start", robot.x(), robot.y(), arena, robot, obstacles);
        if (checkpoints == null) {
            return;
        }
        for (int i = 0; i < checkpoints.size(); i++) {
            WorldSpec.Checkpoint c = checkpoints.get(i);
            if (c != null) {
                placement(checkpointPrefix + "checkpoints[" + i + "]", "checkpoint", c.x(), c.y(), arena, robot, obstacles);
            }
        }
    }

    private static WorldSpec.Robot widest(List<WorldSpec.RobotEntry> robots) {
        WorldSpec.Robot widest = null;
        for (WorldSpec.RobotEntry e : robots) {
            if (e != null && (widest == null || e.robot().radiusM() > widest.radiusM())) {
                widest = e.robot();
            }
        }
        return widest;
    }

    /** Two robots may not start with their bodies overlapping (centres closer than the sum of their radii). */
    private void overlaps(List<WorldSpec.RobotEntry> robots) {
        for (int j = 0; j < robots.size(); j++) {
            for (int i = 0; i < j; i++) {
                WorldSpec.RobotEntry a = robots.get(i);
                WorldSpec.RobotEntry b = robots.get(j);
                if (a == null || b == null) {
                    continue;
                }
                double apart = Math.hypot(a.robot().x() - b.robot().x(), a.robot().y() - b.robot().y());
                double reach = a.robot().radiusM() + b.robot().radiusM();
                if (apart < reach) {
                    problems.add(String.format(Locale.ROOT,
                            "robots[%d]: start (%s, %s) is inside robots[%d] (start (%s, %s)): the centres are %s m apart,"
                                    + " closer than the radii's sum %s m",
                            j, fmt(b.robot().x()), fmt(b.robot().y()), i, fmt(a.robot().x()), fmt(a.robot().y()), fmt(apart),
                            fmt(reach)));
                }
            }
        }
    }

    /** Parses strictly (no comments, no NaN, one value); a syntax error becomes the only problem. */
    private JsonElement readJson(String json) {
        try {
            JsonReader reader = new JsonReader(new StringReader(json));
            reader.setStrictness(Strictness.STRICT);
            if (reader.peek() == JsonToken.END_DOCUMENT) {
                problems.add("(root): malformed JSON: the file is empty");
                return null;
            }
            JsonElement element = new Gson().getAdapter(JsonElement.class).read(reader);
            if (reader.peek() != JsonToken.END_DOCUMENT) {
                problems.add("(root): malformed JSON: something follows the world's closing '}' (a second object, or a '}' too many?)");
                return null;
            }
            return element;
        } catch (IOException | JsonParseException | IllegalStateException e) {
            problems.add("(root): malformed JSON: " + JsonSyntax.describe(e));
            return null;
        }
    }

    // ---- sections ----

    private String name(JsonObject root) {
        JsonElement e = root.get("name");
        if (e == null) {
            problems.add("name: missing required key");
            return null;
        }
        if (!isString(e)) {
            problems.add("name: expected a string, got " + kind(e));
            return null;
        }
        String name = e.getAsString();
        if (!NAME.matcher(name).matches()) {
            problems.add("name: must be letters, digits, '-' or '_' (at least one), got \"" + name + "\"");
            return null;
        }
        return name;
    }

    private Integer timeStep(JsonObject root) {
        Double d = number(root, "", "timeStepMs", false, Bound.ANY, (double) WorldSpec.DEFAULT_TIME_STEP_MS);
        if (d == null) {
            return null;
        }
        if (d != Math.rint(d) || d < 1 || d > 1000) {
            problems.add("timeStepMs: must be an integer from 1 to 1000, got " + fmt(d));
            return null;
        }
        return d.intValue();
    }

    private Long seed(JsonObject root) {
        JsonElement e = root.get("seed");
        if (e == null) {
            return WorldSpec.DEFAULT_SEED;
        }
        if (!isNumber(e)) {
            problems.add("seed: expected an integer, got " + kind(e));
            return null;
        }
        try {
            return new BigDecimal(e.getAsString()).longValueExact();
        } catch (ArithmeticException | NumberFormatException ex) {
            problems.add("seed: must be an integer from " + Long.MIN_VALUE + " to " + Long.MAX_VALUE + ", got " + e.getAsString());
            return null;
        }
    }

    /**
     * @return the named map's cells (read now: its boxes join the obstacles), or null when the world names
     *         none or it cannot be read (a problem recorded)
     */
    private OccupancyGrid map(JsonObject root) {
        if (root.get("map") == null) {
            return null;
        }
        JsonObject o = object(root, "", "map", false);
        if (o == null) {
            return null;
        }
        unknownKeys(o, "map", MAP_KEYS);
        JsonElement f = o.get("file");
        if (f == null) {
            problems.add("map.file: missing required key");
            return null;
        }
        if (!isString(f) || f.getAsString().isBlank()) {
            problems.add("map.file: expected a file name, got " + kind(f));
            return null;
        }
        Double cellM = number(o, "map", "cellM", false, Bound.POSITIVE, MapFiles.DEFAULT_CELL_M);
        if (cellM == null) {
            return null;
        }
        Path file;
        try {
            // normalised: "../maps/x.yaml" must not need the world's folder to exist before the world is written
            file = (baseDir == null ? Path.of("") : baseDir).resolve(f.getAsString()).normalize();
        } catch (InvalidPathException e) {
            problems.add("map.file: not a file name: " + f.getAsString());
            return null;
        }
        if (o.get("cellM") != null && !MapFiles.takesCellSize(file)) {
            problems.add("map.cellM: only a Moving AI map (.map) or a picture alone (.pgm, .png) takes a cell size;"
                    + " a map_server YAML gives its resolution");
            return null;
        }
        if (o.get("cellM") == null && MapFiles.isPicture(file)) {
            problems.add("map.cellM: a picture alone has no scale: give cellM (metres a pixel), or name its map_server YAML");
            return null;
        }
        try {
            OccupancyGrid grid = MapFiles.read(file, cellM).grid();
            mapFile = file;
            return grid;
        } catch (MapException e) {
            problems.add("map.file: " + e.getMessage());
            return null;
        }
    }

    /** @return the arena: a circle, a rectangle, or the map's extent when the file names a map and no arena */
    private WorldSpec.Arena arena(JsonObject root, OccupancyGrid map) {
        if (root.get("arena") == null && map != null) {
            return WorldSpec.Arena.rectangle(map.widthM(), map.heightM(), map.centreX(), map.centreY());
        }
        if (root.get("arena") == null && root.get("map") != null) {
            return null; // the map's own problem is reported
        }
        JsonObject o = object(root, "", "arena", true);
        if (o == null) {
            return null;
        }
        unknownKeys(o, "arena", ARENA_KEYS);
        boolean rectangle = o.has("widthM") || o.has("heightM");
        if (rectangle && o.has("radiusM")) {
            problems.add("arena: give radiusM (a circle) or widthM and heightM (a rectangle), not both");
            return null;
        }
        if (!rectangle) {
            for (String key : List.of("x", "y")) {
                if (o.has(key)) {
                    problems.add("arena." + key + ": only a rectangle has a centre; a circular arena is centred on (0, 0)");
                }
            }
            Double r = number(o, "arena", "radiusM", true, Bound.POSITIVE, null);
            return r == null ? null : new WorldSpec.Arena(r);
        }
        Double w = number(o, "arena", "widthM", true, Bound.POSITIVE, null);
        Double h = number(o, "arena", "heightM", true, Bound.POSITIVE, null);
        Double x = number(o, "arena", "x", false, Bound.ANY, 0.0);
        Double y = number(o, "arena", "y", false, Bound.ANY, 0.0);
        return w == null || h == null || x == null || y == null ? null : WorldSpec.Arena.rectangle(w, h, x, y);
    }

    /** The one robot of a file without {@code robots}; in one with, no {@code robot} may be given. */
    private WorldSpec.Robot robot(JsonObject root, String path) {
        JsonObject o = object(root, "", "robot", true);
        if (o == null) {
            return null;
        }
        unknownKeys(o, path, ROBOT_KEYS);
        return robotProperties(o, path);
    }

    /** @return the robot described by an object's pose and property keys, or null after recording a problem */
    private WorldSpec.Robot robotProperties(JsonObject o, String path) {
        Double x = number(o, path, "x", true, Bound.ANY, null);
        Double y = number(o, path, "y", true, Bound.ANY, null);
        Double h = number(o, path, "headingDeg", true, Bound.ANY, null);
        Double r = number(o, path, "radiusM", false, Bound.POSITIVE, WorldSpec.Robot.DEFAULT_RADIUS_M);
        Double v = number(o, path, "maxSpeedMps", false, Bound.POSITIVE, WorldSpec.Robot.DEFAULT_MAX_SPEED_MPS);
        Double s = number(o, path, "sensorRangeM", false, Bound.POSITIVE, WorldSpec.Robot.DEFAULT_SENSOR_RANGE_M);
        List<Double> angles = sensorAngles(o, path);
        if (x == null || y == null || h == null || r == null || v == null || s == null || angles == null) {
            return null;
        }
        return new WorldSpec.Robot(x, y, h, r, v, s, angles);
    }

    /** @return the distance sensors' angles, the default eight when absent, or null after recording a problem */
    private List<Double> sensorAngles(JsonObject robot, String path) {
        String p = path + ".sensorAnglesDeg";
        JsonElement e = robot.get("sensorAnglesDeg");
        if (e == null) {
            return WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG;
        }
        if (!e.isJsonArray()) {
            problems.add(p + ": expected an array of numbers, got " + kind(e));
            return null;
        }
        JsonArray array = e.getAsJsonArray();
        if (array.isEmpty() || array.size() > MAX_SENSORS) {
            problems.add(p + ": must hold 1 to " + MAX_SENSORS + " angles, got " + array.size());
            return null;
        }
        List<Double> angles = new ArrayList<>();
        for (int i = 0; i < array.size(); i++) {
            JsonElement a = array.get(i);
            String pi = p + "[" + i + "]";
            if (!isNumber(a)) {
                problems.add(pi + ": expected a number, got " + kind(a));
                return null;
            }
            double d = a.getAsDouble();
            if (!(d >= -180 && d <= 180)) {
                problems.add(pi + ": must be from -180 to 180 degrees, got " + a.getAsString());
                return null;
            }
            if (!angles.isEmpty() && d <= angles.get(angles.size() - 1)) {
                problems.add(pi + ": the angles must increase (rightmost sensor first, counter-clockwise), got "
                        + a.getAsString() + " after " + array.get(i - 1).getAsString());
                return null;
            }
            angles.add(d);
        }
        return angles;
    }

    /** @return the obstacles, or null when any is invalid (so placement checks are skipped) */
    private List<WorldSpec.Obstacle> obstacles(JsonObject root) {
        JsonElement e = root.get("obstacles");
        if (e == null) {
            return List.of();
        }
        if (!e.isJsonArray()) {
            problems.add("obstacles: expected an array, got " + kind(e));
            return null;
        }
        JsonArray array = e.getAsJsonArray();
        List<WorldSpec.Obstacle> result = new ArrayList<>();
        boolean allValid = true;
        for (int i = 0; i < array.size(); i++) {
            WorldSpec.Obstacle o = obstacle(array.get(i), "obstacles[" + i + "]");
            allValid &= o != null;
            result.add(o);
        }
        return allValid ? result : null;
    }

    private WorldSpec.Obstacle obstacle(JsonElement e, String path) {
        if (!e.isJsonObject()) {
            problems.add(path + ": expected an object, got " + kind(e));
            return null;
        }
        JsonObject o = e.getAsJsonObject();
        JsonElement shapeElement = o.get("shape");
        if (shapeElement == null) {
            problems.add(path + ".shape: missing required key");
            return null;
        }
        if (!isString(shapeElement)) {
            problems.add(path + ".shape: expected a string, got " + kind(shapeElement));
            return null;
        }
        String shape = shapeElement.getAsString();
        if (WorldSpec.Obstacle.BOX.equals(shape)) {
            unknownKeys(o, path, BOX_KEYS);
            Double x = number(o, path, "x", true, Bound.ANY, null);
            Double y = number(o, path, "y", true, Bound.ANY, null);
            Double w = number(o, path, "widthM", true, Bound.POSITIVE, null);
            Double h = number(o, path, "heightM", true, Bound.POSITIVE, null);
            Double a = number(o, path, "angleDeg", false, Bound.ANY, 0.0);
            if (x == null || y == null || w == null || h == null || a == null) {
                return null;
            }
            return WorldSpec.Obstacle.box(x, y, w, h, a);
        }
        if (WorldSpec.Obstacle.CIRCLE.equals(shape)) {
            unknownKeys(o, path, CIRCLE_KEYS);
            Double x = number(o, path, "x", true, Bound.ANY, null);
            Double y = number(o, path, "y", true, Bound.ANY, null);
            Double r = number(o, path, "radiusM", true, Bound.POSITIVE, null);
            if (x == null || y == null || r == null) {
                return null;
            }
            return WorldSpec.Obstacle.circle(x, y, r);
        }
        problems.add(path + ".shape: unknown shape \"" + shape + "\" (expected \"box\" or \"circle\")");
        return null;
    }

    /** @return the checkpoints, possibly with null entries for invalid ones, or null when unusable */
    /**
     * @param owner  the object holding {@code checkpoints}: the root, or a {@code robots} entry
     * @param prefix the owner's key path and a dot ("" for the root)
     */
    private List<WorldSpec.Checkpoint> checkpoints(JsonObject owner, String prefix) {
        String key = prefix + "checkpoints";
        JsonElement e = owner.get("checkpoints");
        if (e == null) {
            problems.add(key + ": missing required key");
            return null;
        }
        if (!e.isJsonArray()) {
            problems.add(key + ": expected an array, got " + kind(e));
            return null;
        }
        JsonArray array = e.getAsJsonArray();
        if (array.isEmpty()) {
            problems.add(key + ": must list at least one checkpoint");
            return null;
        }
        List<WorldSpec.Checkpoint> result = new ArrayList<>();
        for (int i = 0; i < array.size(); i++) {
            String path = key + "[" + i + "]";
            JsonElement c = array.get(i);
            if (!c.isJsonObject()) {
                problems.add(path + ": expected an object, got " + kind(c));
                result.add(null);
                continue;
            }
            unknownKeys(c.getAsJsonObject(), path, POINT_KEYS);
            Double x = number(c.getAsJsonObject(), path, "x", true, Bound.ANY, null);
            Double y = number(c.getAsJsonObject(), path, "y", true, Bound.ANY, null);
            result.add(x == null || y == null ? null : new WorldSpec.Checkpoint(x, y));
        }
        return java.util.Collections.unmodifiableList(result);
    }

    /**
     * @return the stations: {@code rechargeStation} alone, or every one of {@code rechargeStations}; null when
     *         unusable, with null entries for invalid ones (a problem recorded for each)
     */
    private List<WorldSpec.RechargeStation> stations(JsonObject root) {
        if (!root.has("rechargeStations")) {
            JsonObject o = object(root, "", "rechargeStation", true);
            WorldSpec.RechargeStation st = o == null ? null : station(o, "rechargeStation");
            return st == null ? null : List.of(st);
        }
        if (root.has("rechargeStation")) {
            problems.add("rechargeStation: give rechargeStation (one) or rechargeStations (several), not both");
            return null;
        }
        JsonElement e = root.get("rechargeStations");
        if (!e.isJsonArray()) {
            problems.add("rechargeStations: expected an array, got " + kind(e));
            return null;
        }
        JsonArray array = e.getAsJsonArray();
        if (array.isEmpty()) {
            problems.add("rechargeStations: must list at least one station");
            return null;
        }
        List<WorldSpec.RechargeStation> result = new ArrayList<>();
        boolean allValid = true;
        for (int i = 0; i < array.size(); i++) {
            String path = "rechargeStations[" + i + "]";
            JsonElement s = array.get(i);
            WorldSpec.RechargeStation st = null;
            if (!s.isJsonObject()) {
                problems.add(path + ": expected an object, got " + kind(s));
            } else {
                st = station(s.getAsJsonObject(), path);
            }
            allValid &= st != null;
            result.add(st);
        }
        return allValid ? Collections.unmodifiableList(result) : null;
    }

    private WorldSpec.RechargeStation station(JsonObject o, String path) {
        unknownKeys(o, path, STATION_KEYS);
        Double x = number(o, path, "x", true, Bound.ANY, null);
        Double y = number(o, path, "y", true, Bound.ANY, null);
        Double r = number(o, path, "radiusM", true, Bound.POSITIVE, null);
        return x == null || y == null || r == null ? null : new WorldSpec.RechargeStation(x, y, r);
    }

    /**
     * The robots of a world that lists several (docs/world-file.md, "Several robots"): each entry takes every key
     * {@code robot} takes, a positive id distinct from the others' and its own {@code checkpoints}.
     *
     * @return the robots, with null entries for invalid ones, or null when the list is unusable
     */
    private List<WorldSpec.RobotEntry> robots(JsonObject root) {
        if (root.has("robot")) {
            problems.add("robot: a world with \"robots\" describes each robot there; give robots or robot, not both");
        }
        if (root.has("checkpoints")) {
            problems.add("checkpoints: a world with \"robots\" gives each robot its checkpoints in its entry;"
                    + " give robots or checkpoints, not both");
        }
        JsonElement e = root.get("robots");
        if (!e.isJsonArray()) {
            problems.add("robots: expected an array, got " + kind(e));
            return null;
        }
        JsonArray array = e.getAsJsonArray();
        if (array.isEmpty()) {
            problems.add("robots: must list at least one robot");
            return null;
        }
        List<WorldSpec.RobotEntry> result = new ArrayList<>();
        Map<Integer, Integer> indexOfId = new HashMap<>();
        for (int i = 0; i < array.size(); i++) {
            String path = "robots[" + i + "]";
            JsonElement element = array.get(i);
            if (!element.isJsonObject()) {
                problems.add(path + ": expected an object, got " + kind(element));
                result.add(null);
                continue;
            }
            JsonObject o = element.getAsJsonObject();
            unknownKeys(o, path, FLEET_ROBOT_KEYS);
            Integer id = robotId(o, path);
            if (id != null && indexOfId.putIfAbsent(id, i) != null) {
                problems.add(path + ".id: " + id + " is robots[" + indexOfId.get(id) + "]'s id too; ids must be distinct");
            }
            WorldSpec.Robot robot = robotProperties(o, path);
            List<WorldSpec.Checkpoint> checkpoints = checkpoints(o, path + ".");
            if (id == null || robot == null || checkpoints == null || checkpoints.contains(null)) {
                result.add(null);
                continue;
            }
            result.add(new WorldSpec.RobotEntry(id, robot, checkpoints));
        }
        return Collections.unmodifiableList(result);
    }

    /** @return a {@code robots} entry's id (a positive integer), or null after recording a problem */
    private Integer robotId(JsonObject o, String path) {
        String p = path + ".id";
        JsonElement e = o.get("id");
        if (e == null) {
            problems.add(p + ": missing required key");
            return null;
        }
        if (!isNumber(e)) {
            problems.add(p + ": expected an integer, got " + kind(e));
            return null;
        }
        double d = e.getAsDouble();
        if (d != Math.rint(d) || d < 1 || d > Integer.MAX_VALUE) {
            problems.add(p + ": must be a positive integer (the robot's robot_id), got " + e.getAsString());
            return null;
        }
        return (int) d;
    }

    private WorldSpec.Battery battery(JsonObject root) {
        if (root.get("battery") == null) {
            return WorldSpec.Battery.DEFAULT;
        }
        JsonObject o = object(root, "", "battery", false);
        if (o == null) {
            return null;
        }
        unknownKeys(o, "battery", BATTERY_KEYS);
        WorldSpec.Battery d = WorldSpec.Battery.DEFAULT;
        Double initial = number(o, "battery", "initial", false, Bound.POSITIVE_PERCENT, d.initial());
        Double drain = number(o, "battery", "drainPerMeter", false, Bound.NON_NEGATIVE, d.drainPerMeter());
        Double to = number(o, "battery", "rechargeTo", false, Bound.POSITIVE_PERCENT, d.rechargeTo());
        Double rate = number(o, "battery", "rechargeRatePerS", false, Bound.POSITIVE, d.rechargeRatePerS());
        if (initial == null || drain == null || to == null || rate == null) {
            return null;
        }
        return new WorldSpec.Battery(initial, drain, to, rate);
    }

    /** Checks that the robot's centre can be at (x, y): inside the arena and clear of every obstacle. */
    private void placement(String path, String what, double x, double y, WorldSpec.Arena arena, WorldSpec.Robot robot,
                           List<WorldSpec.Obstacle> obstacles) {
        if (arena.isCircle()) {
            double reach = arena.radiusM() - robot.radiusM();
            double from = Math.sqrt(x * x + y * y);
            if (from > reach) {
                problems.add(String.format(Locale.ROOT,
                        "%s: %s (%s, %s) is outside the arena: %s m from the centre, but the robot's centre (radius %s m) "
                                + "stays within %s m",
                        path, what, fmt(x), fmt(y), fmt(from), fmt(robot.radiusM()), fmt(reach)));
            }
        } else if (arena.inside(x, y) < robot.radiusM()) {
            double r = robot.radiusM();
            problems.add(String.format(Locale.ROOT,
                    "%s: %s (%s, %s) is outside the arena: the robot's centre (radius %s m) stays within x %s to %s and y %s to %s",
                    path, what, fmt(x), fmt(y), fmt(r), fmt(arena.minX() + r), fmt(arena.maxX() - r), fmt(arena.minY() + r),
                    fmt(arena.maxY() - r)));
        }
        for (int i = 0; i < obstacles.size(); i++) {
            double gap = obstacles.get(i).distanceTo(x, y);
            if (gap < robot.radiusM()) {
                if (i >= listedObstacles) { // one line for the map, however many of its boxes are in the way
                    problems.add(String.format(Locale.ROOT,
                            "%s: %s (%s, %s) is on a wall of the map %s (occupied or unknown cells): the robot (radius %s m) would overlap it",
                            path, what, fmt(x), fmt(y), mapFile, fmt(robot.radiusM())));
                    break;
                }
                problems.add(String.format(Locale.ROOT,
                        "%s: %s (%s, %s) is inside obstacle obstacles[%d]: the robot (radius %s m) would overlap it",
                        path, what, fmt(x), fmt(y), i, fmt(robot.radiusM())));
            }
        }
    }

    // ---- helpers ----

    private void unknownKeys(JsonObject o, String path, Set<String> allowed) {
        for (Map.Entry<String, JsonElement> entry : o.entrySet()) {
            if (!allowed.contains(entry.getKey())) {
                problems.add(join(path, entry.getKey()) + ": unknown key (expected one of "
                        + allowed.stream().sorted().toList() + ")");
            }
        }
    }

    private JsonObject object(JsonObject parent, String path, String key, boolean required) {
        JsonElement e = parent.get(key);
        if (e == null) {
            if (required) {
                problems.add(join(path, key) + ": missing required key");
            }
            return null;
        }
        if (!e.isJsonObject()) {
            problems.add(join(path, key) + ": expected an object, got " + kind(e));
            return null;
        }
        return e.getAsJsonObject();
    }

    /** @return the number, its default when absent and optional, or null after recording a problem */
    private Double number(JsonObject o, String path, String key, boolean required, Bound bound, Double dflt) {
        String p = join(path, key);
        JsonElement e = o.get(key);
        if (e == null) {
            if (required) {
                problems.add(p + ": missing required key");
            }
            return dflt;
        }
        if (!isNumber(e)) {
            problems.add(p + ": expected a number, got " + kind(e));
            return null;
        }
        double d = e.getAsDouble();
        if (!Double.isFinite(d)) {
            problems.add(p + ": must be a finite number, got " + e.getAsString());
            return null;
        }
        String rule = switch (bound) {
            case ANY -> null;
            case POSITIVE -> d > 0 ? null : "must be > 0";
            case NON_NEGATIVE -> d >= 0 ? null : "must be >= 0";
            case POSITIVE_PERCENT -> d > 0 && d <= 100 ? null : "must be > 0 and <= 100";
        };
        if (rule != null) {
            problems.add(p + ": " + rule + ", got " + e.getAsString());
            return null;
        }
        return d;
    }

    private static boolean isNumber(JsonElement e) {
        return e.isJsonPrimitive() && e.getAsJsonPrimitive().isNumber();
    }

    private static boolean isString(JsonElement e) {
        return e.isJsonPrimitive() && e.getAsJsonPrimitive().isString();
    }

    private static String kind(JsonElement e) {
        if (e.isJsonNull()) {
            return "null";
        }
        if (e.isJsonObject()) {
            return "an object";
        }
        if (e.isJsonArray()) {
            return "an array";
        }
        JsonPrimitive p = e.getAsJsonPrimitive();
        if (p.isBoolean()) {
            return "a boolean (" + p.getAsBoolean() + ")";
        }
        if (p.isString()) {
            return "a string (\"" + p.getAsString() + "\")";
        }
        return "a number (" + p.getAsString() + ")";
    }

    private static String join(String path, String key) {
        return path.isEmpty() ? key : path + "." + key;
    }

    private static String fmt(double d) {
        return String.format(Locale.ROOT, "%.2f", d);
    }
}
