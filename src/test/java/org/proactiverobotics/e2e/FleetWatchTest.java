package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.util.ArrayList;
import java.util.List;
import org.h2.jdbcx.JdbcDataSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.replay.LiveMission;
import org.proactiverobotics.app.replay.WatchServer;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The live view ({@code watch --world W}) of a world with several robots, from the database a real run left: the
 * page carries every robot (the picker's data), and {@code /steps?from=K1,K2,...} answers each robot's commands
 * from its own K on, as many as the database holds for its {@code robot_id}. A one-robot view stays as it was.
 */
class FleetWatchTest extends CommandLineTest {

    @TempDir
    Path tmp;

    private static String get(HttpClient http, InetSocketAddress at, String path) throws Exception {
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + at.getPort() + path)).build(),
                HttpResponse.BodyHandlers.ofString());
        assertThat(r.statusCode()).as(path).isEqualTo(200);
        return r.body();
    }

    private static long commands(JdbcDataSource pool, int robotId) throws Exception {
        try (Connection c = pool.getConnection();
             PreparedStatement ps = c.prepareStatement("SELECT COUNT(*) FROM engine_comments WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                rs.next();
                return rs.getLong(1);
            }
        }
    }

    @Test
    void everyRobotIsServedFromItsOwnRowsAndTheOneRobotPageHasNoPicker() throws Exception {
        WorldSpec world = FleetMissionTest.crossing(6.0); // its first 6 s: enough rows for each robot, and quick
        Path file = tmp.resolve("crossing.json");
        Files.writeString(file, WorldJson.of(world));
        String url = "jdbc:h2:file:" + tmp.resolve("db").resolve("p") + ";MODE=MySQL;DATABASE_TO_LOWER=TRUE";
        assertThat(run("run", "--world", file.toString(), "--db", url, "--db-user", "sa", "--db-password", "", "--quiet",
                "--out", tmp.resolve("out").toString())).as(err.toString()).isIn(0, 1);
        JdbcDataSource pool = new JdbcDataSource();
        pool.setURL(url);
        pool.setUser("sa");
        pool.setPassword("");
        List<LiveMission> missions = new ArrayList<>();
        for (WorldSpec.RobotEntry r : world.robots()) {
            LiveMission m = new LiveMission(pool, r.id());
            while (m.poll() > 0) {
                // every kept command of its mission
            }
            missions.add(m);
        }
        HttpClient http = HttpClient.newHttpClient();
        try (WatchServer server = new WatchServer(new InetSocketAddress("127.0.0.1", 0), world, missions)) {
            String page = get(http, server.address(), "/");
            assertThat(page).contains("<select id=\"robot\">").contains("\"robots\":[{\"id\":1,");

            JsonArray all = JsonParser.parseString(get(http, server.address(), "/steps?from=0,0,0")).getAsJsonObject()
                    .getAsJsonArray("robots");
            assertThat(all).hasSize(3);
            int[] ids = {1, 2, 5};
            for (int i = 0; i < 3; i++) {
                JsonObject part = all.get(i).getAsJsonObject();
                assertThat(part.get("count").getAsLong()).as("robot %d", ids[i]).isEqualTo(commands(pool, ids[i])).isPositive();
            }
            int firstCount = all.get(0).getAsJsonObject().get("count").getAsInt();
            JsonArray later = JsonParser.parseString(get(http, server.address(), "/steps?from=" + firstCount + ",10"))
                    .getAsJsonObject().getAsJsonArray("robots");
            assertThat(later.get(0).getAsJsonObject().get("count").getAsInt()).isZero();
            assertThat(later.get(1).getAsJsonObject().get("from").getAsInt()).isEqualTo(10);
            assertThat(later.get(1).getAsJsonObject().get("count").getAsLong()).isEqualTo(commands(pool, 2) - 10);
            assertThat(later.get(2).getAsJsonObject().get("from").getAsInt()).isZero();
        }
        try (WatchServer one = new WatchServer(new InetSocketAddress("127.0.0.1", 0), missions.get(0), world.forRobot(0), 1)) {
            String page = get(http, one.address(), "/");
            assertThat(page).doesNotContain("id=\"robot\"").doesNotContain("FLEET");
        }
    }
}
