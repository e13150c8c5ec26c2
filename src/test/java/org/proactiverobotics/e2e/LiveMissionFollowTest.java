package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonArray;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import javax.sql.DataSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.replay.LiveMission;

/**
 * The live view (watch) follows a robot's commands by iteration, not by id: on a Galera cluster a
 * later iteration's row may have a smaller id. A new run (commands cleared, iterations from 1) is
 * seen as one and followed from its start.
 */
class LiveMissionFollowTest extends CommandLineTest {

    @TempDir
    Path tmp;

    private static List<Long> iterations(LiveMission live) {
        JsonArray column = live.data().toJson(0).getAsJsonArray("iteration");
        List<Long> out = new ArrayList<>();
        column.forEach(e -> out.add(e.getAsLong()));
        return out;
    }

    private static void command(Statement s, long id, long iteration) throws Exception {
        s.executeUpdate("INSERT INTO engine_comments (id, robot_id, iteration, sim_time_ms, scenario, command) VALUES ("
                + id + ", 1, " + iteration + ", " + 32 * iteration + ", 'ReachDestination', 'FORWARD 0.2')");
    }

    @Test
    void commandsAreFollowedByIterationThroughInterleavedIdsAndANewRun() throws Exception {
        DataSource pool = missionInH2File(tmp, "--world", "reference-arena");
        LiveMission live = new LiveMission(pool, 1);
        while (live.poll() > 0) {
            // every kept command of the mission
        }
        long kept;
        try (Connection c = pool.getConnection(); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT COUNT(*) FROM engine_comments WHERE robot_id = 1")) {
            rs.next();
            kept = rs.getLong(1);
        }
        assertThat((long) live.data().size()).isEqualTo(kept);

        try (Connection c = pool.getConnection(); Statement s = c.createStatement()) {
            s.executeUpdate("DELETE FROM engine_comments WHERE robot_id = 1"); // a new run: its engine clears them
            command(s, 900_003, 1);
            command(s, 900_002, 2); // ids going down as iterations go up, as from a node whose counter is behind
            command(s, 900_001, 3);
        }
        assertThat(live.poll()).isEqualTo(3);
        assertThat(iterations(live)).containsExactly(1L, 2L, 3L);

        try (Connection c = pool.getConnection(); Statement s = c.createStatement()) {
            command(s, 17, 4);
        }
        assertThat(live.poll()).as("a later iteration with a smaller id is read").isEqualTo(1);
        assertThat(iterations(live)).containsExactly(1L, 2L, 3L, 4L);
        assertThat(live.poll()).isZero();
    }
}
