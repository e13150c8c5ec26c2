package org.proactiverobotics.app.foxglove;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The Foxglove layout of a world with several robots, written beside its run.mcap
 * ({@value #FILE_NAME}): the shipped one-robot layout (docs/foxglove-layout.json) with each of its
 * topics named once per robot, under {@code /robot/ID} as the file has them. The 3D panel shows
 * every robot's map, scan, pose and believed pose; the winner and battery panels one line per
 * robot; the raw-message and log panels the first robot's (pick another in the panel).
 */
public final class FleetLayout {

    /** The file's name, beside run.mcap. */
    public static final String FILE_NAME = "foxglove-layout.json";

    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();

    private FleetLayout() {
    }

    /**
     * Writes the layout.
     *
     * @param file  where
     * @param world the world (its robots' ids name the topics)
     * @throws IOException when it cannot be written
     */
    public static void write(Path file, WorldSpec world) throws IOException {
        Files.writeString(file, GSON.toJson(of(world)) + "\n", StandardCharsets.UTF_8);
    }

    /**
     * @param world the world
     * @return the layout, as Foxglove imports it
     */
    public static JsonObject of(WorldSpec world) {
        List<Integer> ids = world.robots().stream().map(WorldSpec.RobotEntry::id).toList();
        JsonObject layout = oneRobot();
        for (Map.Entry<String, JsonElement> panel : layout.getAsJsonObject("configById").entrySet()) {
            JsonObject config = panel.getValue().getAsJsonObject();
            if (config.has("topics")) { // the 3D panel: every robot's own topics; /world is the world's
                JsonObject topics = new JsonObject();
                for (Map.Entry<String, JsonElement> t : config.getAsJsonObject("topics").entrySet()) {
                    if (t.getKey().equals("/world")) {
                        topics.add(t.getKey(), t.getValue());
                        continue;
                    }
                    for (int id : ids) {
                        topics.add(prefix(id) + t.getKey(), t.getValue().deepCopy());
                    }
                }
                config.add("topics", topics);
            }
            if (config.has("paths")) { // a line per robot, labelled with its id
                JsonArray paths = new JsonArray();
                for (JsonElement path : config.getAsJsonArray("paths")) {
                    for (int id : ids) {
                        JsonObject p = path.getAsJsonObject().deepCopy();
                        p.addProperty("value", prefix(id) + p.get("value").getAsString());
                        String label = p.has("label") ? p.get("label").getAsString() : "";
                        p.addProperty("label", ("robot " + id + " " + label).strip());
                        paths.add(p);
                    }
                }
                config.add("paths", paths);
            }
            for (String key : List.of("topicPath", "topicToRender")) { // one robot's at a time: the first's
                if (config.has(key)) {
                    config.addProperty(key, prefix(ids.get(0)) + config.get(key).getAsString());
                }
            }
        }
        return layout;
    }

    private static String prefix(int id) {
        return "/robot/" + id;
    }

    /** @return the shipped one-robot layout, a fresh copy */
    static JsonObject oneRobot() {
        try (InputStream in = FleetLayout.class.getResourceAsStream(FILE_NAME)) {
            if (in == null) {
                throw new IllegalStateException(FILE_NAME + " is missing from the application jar");
            }
            return JsonParser.parseString(new String(in.readAllBytes(), StandardCharsets.UTF_8)).getAsJsonObject();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
