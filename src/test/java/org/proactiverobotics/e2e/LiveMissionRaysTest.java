package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.replay.LiveMission;
import org.proactiverobotics.app.replay.ReplayData;

/** The live view (watch) draws the robot's own rays, as its readings give them, not the default twelve. */
class LiveMissionRaysTest extends CommandLineTest {

    @TempDir
    Path tmp;

    @Test
    void aRobotWithItsOwnRaysIsDrawnWithThem() throws Exception {
        JsonObject world = JsonParser.parseString(Files.readString(Path.of("..", "worlds", "reference-arena.json")))
                .getAsJsonObject();
        JsonArray angles = new JsonArray();
        for (double deg : new double[] {-75, -30, 0, 30, 75}) {
            angles.add(deg);
        }
        JsonObject robot = world.getAsJsonObject("robot");
        robot.add("sensorAnglesDeg", angles);
        robot.addProperty("sensorRangeM", 1.5);
        Path file = tmp.resolve("five-rays.json");
        Files.writeString(file, new Gson().toJson(world));
        LiveMission live = new LiveMission(missionInH2File(tmp, "--world", file.toString()), 1);
        while (live.poll() > 0) {
            // read every kept command
        }
        JsonArray drawn = live.mission().getAsJsonArray("sensorAnglesRad");
        assertThat(drawn).hasSize(5);
        assertThat(drawn.get(0).getAsDouble()).isCloseTo(Math.toRadians(-75), org.assertj.core.data.Offset.offset(1e-9));
        assertThat(drawn.get(4).getAsDouble()).isCloseTo(Math.toRadians(75), org.assertj.core.data.Offset.offset(1e-9));
        assertThat(live.mission().get("sensorRangeM").getAsDouble()).isEqualTo(1.5);
        ReplayData data = live.data();
        assertThat(data.size()).isPositive();
        JsonObject json = data.toJson(0);
        assertThat(json.get("rays").getAsInt()).isEqualTo(5);
        JsonArray scan = json.getAsJsonArray("scan");
        assertThat(scan).hasSize(data.size() * 5);
        long read = 0;
        for (int k = 0; k < scan.size(); k++) {
            if (scan.get(k).getAsInt() != ReplayData.NONE) {
                read++;
            }
        }
        assertThat(read).as("readings of every ray, the fifth included").isGreaterThan(scan.size() / 2);
    }
}
