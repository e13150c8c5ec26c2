package org.proactiverobotics.app.replay;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * replay.html: the template in resources ({@code replay/replay.html}) with the world, the
 * scenarios' colours and the mission's steps inline as JSON. The page fetches nothing; the live
 * view ({@code watch}) serves the same template and adds the steps as they come.
 */
public final class ReplayPage {

    /** Who made the page, which decides what it can show. */
    public enum Source {
        /** The one-process mission: every decision of the engine. */
        RUN,
        /** The robot process: what the robot knows (pose, readings, the commands it got). */
        ROBOT,
        /** The live view of a database. */
        WATCH
    }

    private static final String DATA_MARK = "/*REPLAY_DATA*/null";
    /**
     * The template's parts for a world of several robots, cut from a one-robot page so that it stays what it was:
     * whole lines (the mark at a line's start), pieces of a line, and pieces of HTML.
     */
    private static final Pattern FLEET_LINES = Pattern.compile("(?m)^[ \\t]*/\\*FLEET\\{\\*/(?s:.*?)/\\*\\}FLEET\\*/\\n");
    private static final Pattern FLEET_PIECES = Pattern.compile("/\\*FLEET\\{\\*/(?s:.*?)/\\*\\}FLEET\\*/");
    private static final Pattern FLEET_HTML = Pattern.compile("<!--FLEET\\{-->(?s:.*?)<!--\\}FLEET-->");
    /** HTML-safe: a scenario named {@code </script>} stays inside its string. */
    private static final Gson GSON = new Gson();

    private ReplayPage() {
    }

    /**
     * Writes replay.html.
     *
     * @param file    where
     * @param source  who made it
     * @param world   the world (null: unknown, the page draws what the data has)
     * @param colours colour by scenario name ({@code ScenarioColours})
     * @param data    the steps
     * @param summary one line on how the mission went
     * @throws IOException when it cannot be written
     */
    public static void write(Path file, Source source, WorldSpec world, Map<String, String> colours, ReplayData data,
                             String summary) throws IOException {
        Files.writeString(file, html(header(source, world, colours, summary, data.toJson(0))));
    }

    /**
     * Writes the replay.html of a world with several robots: every robot drawn, the record of the one picked.
     *
     * @param file    where
     * @param source  who made it
     * @param world   the world (its arena, obstacles and stations are drawn)
     * @param colours colour by scenario name
     * @param robots  every robot with its steps, in the world's order
     * @param summary one line on how the whole run went
     * @throws IOException when it cannot be written
     */
    public static void writeFleet(Path file, Source source, WorldSpec world, Map<String, String> colours,
                                  List<ReplayRobot> robots, String summary) throws IOException {
        JsonObject data = header(source, world, colours, summary, null);
        fleet(data, world, robots);
        Files.writeString(file, html(data));
    }

    /**
     * Makes a page's data that of a world with several robots: every robot, and every station of the world.
     *
     * @param data   the page's data ({@link #header})
     * @param world  the world, or null
     * @param robots every robot with its steps so far
     */
    public static void fleet(JsonObject data, WorldSpec world, List<ReplayRobot> robots) {
        data.add("robots", ReplayRobot.toJson(robots, 0));
        if (world != null && data.get("world").isJsonObject()) {
            JsonArray stations = new JsonArray();
            for (WorldSpec.RechargeStation s : world.rechargeStations()) {
                JsonObject st = new JsonObject();
                st.addProperty("x", s.x());
                st.addProperty("y", s.y());
                st.addProperty("radiusM", s.radiusM());
                stations.add(st);
            }
            data.getAsJsonObject("world").add("stations", stations);
        }
    }

    /**
     * @param data the page's data object ({@link #header}; with {@code robots} for a world of several)
     * @return the page with the data inline
     */
    public static String html(JsonObject data) {
        String template = template(data.has("robots"));
        int at = template.indexOf(DATA_MARK);
        if (at < 0) {
            throw new IllegalStateException("replay.html template has no " + DATA_MARK);
        }
        return template.substring(0, at) + GSON.toJson(data) + template.substring(at + DATA_MARK.length());
    }

    /**
     * @param source  who made it
     * @param world   the world, or null
     * @param colours colour by scenario
     * @param summary one line on how the mission went (may be empty)
     * @param steps   {@link ReplayData#toJson(int)}
     * @return the page's data object
     */
    public static JsonObject header(Source source, WorldSpec world, Map<String, String> colours, String summary,
                                    JsonObject steps) {
        JsonObject o = new JsonObject();
        o.addProperty("source", source.name().toLowerCase(java.util.Locale.ROOT));
        o.addProperty("summary", summary);
        o.add("world", world == null ? null : world(world));
        JsonObject c = new JsonObject();
        colours.forEach(c::addProperty);
        o.add("colours", c);
        o.add("steps", steps);
        return o;
    }

    /** The world as the page draws it: metres and radians. */
    public static JsonObject world(WorldSpec w) {
        JsonObject o = new JsonObject();
        o.addProperty("name", w.name());
        if (w.arena().isCircle()) {
            o.addProperty("arenaRadiusM", w.arena().radiusM());
        } else { // a rectangle: its corners
            JsonObject r = new JsonObject();
            r.addProperty("x0", w.arena().minX());
            r.addProperty("y0", w.arena().minY());
            r.addProperty("x1", w.arena().maxX());
            r.addProperty("y1", w.arena().maxY());
            o.add("arenaRect", r);
        }
        o.addProperty("robotRadiusM", w.robot().radiusM());
        o.addProperty("sensorRangeM", w.robot().sensorRangeM());
        o.addProperty("timeStepMs", w.timeStepMs());
        JsonArray angles = new JsonArray();
        for (double deg : w.robot().sensorAnglesDeg()) {
            angles.add(Math.toRadians(deg));
        }
        o.add("sensorAnglesRad", angles);
        JsonArray obstacles = new JsonArray();
        for (WorldSpec.Obstacle ob : w.obstacles()) {
            JsonObject b = new JsonObject();
            b.addProperty("shape", ob.shape());
            b.addProperty("x", ob.x());
            b.addProperty("y", ob.y());
            b.addProperty("widthM", ob.widthM());
            b.addProperty("heightM", ob.heightM());
            b.addProperty("angleRad", ob.angleRad());
            b.addProperty("radiusM", ob.radiusM());
            obstacles.add(b);
        }
        o.add("obstacles", obstacles);
        JsonArray checkpoints = new JsonArray();
        for (WorldSpec.Checkpoint cp : w.checkpoints()) {
            JsonObject p = new JsonObject();
            p.addProperty("x", cp.x());
            p.addProperty("y", cp.y());
            checkpoints.add(p);
        }
        o.add("checkpoints", checkpoints);
        o.addProperty("checkpointRadiusM", w.checkpointRadiusM());
        JsonObject st = new JsonObject();
        st.addProperty("x", w.rechargeStation().x());
        st.addProperty("y", w.rechargeStation().y());
        st.addProperty("radiusM", w.rechargeStation().radiusM());
        o.add("station", st);
        return o;
    }

    /**
     * @param fleet whether the page shows a world of several robots
     * @return the template, its fleet parts kept or cut out
     */
    public static String template(boolean fleet) {
        String t = template();
        if (fleet) {
            return t;
        }
        t = FLEET_LINES.matcher(t).replaceAll("");
        t = FLEET_PIECES.matcher(t).replaceAll("");
        return FLEET_HTML.matcher(t).replaceAll("");
    }

    /** @return the template as the jar holds it (with the fleet parts) */
    public static String template() {
        try (InputStream in = ReplayPage.class.getResourceAsStream("/replay/replay.html")) {
            if (in == null) {
                throw new IllegalStateException("replay/replay.html is missing from the jar");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
