package org.proactiverobotics.app.replay;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.proactiverobotics.app.mission.ScenarioColours;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The live view's HTTP server (the JDK's {@link HttpServer}): {@code /} is replay.html with no
 * steps, which polls {@code /steps?from=K} for the steps from K on, as {@link LiveMission} read
 * them. GET only; nothing it serves writes to the database.
 * <p>
 * A world of several robots (docs/replay.md, "Several robots") is followed robot by robot, one {@link LiveMission} each: the page
 * draws every robot and shows the picked one's record, and {@code /steps?from=K1,K2,...} answers
 * {@code {"status": ..., "robots": [part, ...]}}, each robot's steps from its K on, in the world's order.
 */
public final class WatchServer implements AutoCloseable {

    private static final Gson GSON = new Gson();

    private final HttpServer server;
    private final ExecutorService threads = Executors.newFixedThreadPool(2, r -> {
        Thread t = new Thread(r, "watch-http");
        t.setDaemon(true);
        return t;
    });
    private final LiveMission mission;
    private final WorldSpec world;
    private final int robotId;
    /** Every robot followed, in the world's order, when the world has several; empty otherwise. */
    private final List<LiveMission> fleet;
    private volatile String status = "";

    /**
     * Binds and starts serving.
     *
     * @param address where to listen
     * @param mission what to show
     * @param world   the world file, to draw the arena and obstacles; null: the checkpoints and station only
     * @param robotId the robot shown
     * @throws IOException when the address cannot be bound (a {@link java.net.BindException} when in use)
     */
    public WatchServer(InetSocketAddress address, LiveMission mission, WorldSpec world, int robotId) throws IOException {
        this(address, mission, world, robotId, List.of());
    }

    /**
     * Binds and starts serving a world of several robots.
     *
     * @param address where to listen
     * @param world   the world file, with every robot
     * @param fleet   one live mission per robot of the world, in its order
     * @throws IOException when the address cannot be bound
     */
    public WatchServer(InetSocketAddress address, WorldSpec world, List<LiveMission> fleet) throws IOException {
        this(address, fleet.get(0), world, world.robots().get(0).id(), List.copyOf(fleet));
    }

    private WatchServer(InetSocketAddress address, LiveMission mission, WorldSpec world, int robotId,
                        List<LiveMission> fleet) throws IOException {
        this.mission = mission;
        this.world = world;
        this.robotId = robotId;
        this.fleet = fleet;
        this.server = HttpServer.create(address, 16);
        server.createContext("/", this::page);
        server.createContext("/steps", this::steps);
        server.setExecutor(threads);
        server.start();
    }

    /** @return the bound address (the port when 0 was asked) */
    public InetSocketAddress address() {
        return server.getAddress();
    }

    /** @param text a status line the page shows (database trouble), empty when all is well */
    public void status(String text) {
        this.status = text;
    }

    private void page(HttpExchange ex) throws IOException {
        if (!allowed(ex)) {
            return;
        }
        if ("/favicon.ico".equals(ex.getRequestURI().getPath())) {
            ex.sendResponseHeaders(204, -1); // no icon: the browser asks anyway
            ex.close();
            return;
        }
        if (!"/".equals(ex.getRequestURI().getPath()) && !"/index.html".equals(ex.getRequestURI().getPath())) {
            send(ex, 404, "text/plain; charset=utf-8", "not found: " + ex.getRequestURI().getPath());
            return;
        }
        JsonObject data = ReplayPage.header(ReplayPage.Source.WATCH, world, ScenarioColours.of(mission.slots()),
                "robot " + robotId + ", live from the database", null);
        data.addProperty("robotId", robotId);
        if (!fleet.isEmpty()) {
            List<ReplayRobot> robots = new ArrayList<>();
            for (int i = 0; i < fleet.size(); i++) {
                WorldSpec.RobotEntry entry = world.robots().get(i);
                robots.add(new ReplayRobot(entry.id(), null, "robot " + entry.id() + " of " + fleet.size()
                        + ", live from the database", entry, fleet.get(i).data()));
            }
            ReplayPage.fleet(data, world, robots);
        }
        send(ex, 200, "text/html; charset=utf-8", ReplayPage.html(data));
    }

    private void steps(HttpExchange ex) throws IOException {
        if (!allowed(ex)) {
            return;
        }
        if (!fleet.isEmpty()) {
            fleetSteps(ex);
            return;
        }
        int from = 0;
        String query = ex.getRequestURI().getQuery();
        if (query != null) {
            for (String pair : query.split("&")) {
                if (pair.startsWith("from=")) {
                    try {
                        from = Math.max(0, Integer.parseInt(pair.substring(5)));
                    } catch (NumberFormatException e) {
                        send(ex, 400, "text/plain; charset=utf-8", "from must be a step number");
                        return;
                    }
                }
            }
        }
        ReplayData data = mission.data();
        if (from > data.size()) {
            from = 0; // a new run started: the page starts over
        }
        JsonObject part = data.toJson(from);
        part.addProperty("status", status);
        if (world == null && mission.mission() != null) {
            part.add("world", mission.mission());
        }
        send(ex, 200, "application/json; charset=utf-8", GSON.toJson(part));
    }

    /** {@code /steps?from=K1,K2,...}: each robot's steps from its K on (0 where the list is short). */
    private void fleetSteps(HttpExchange ex) throws IOException {
        int[] from = new int[fleet.size()];
        String query = ex.getRequestURI().getQuery();
        if (query != null) {
            for (String pair : query.split("&")) {
                if (pair.startsWith("from=")) {
                    String[] each = pair.substring(5).split(",");
                    for (int i = 0; i < Math.min(each.length, from.length); i++) {
                        try {
                            from[i] = Math.max(0, Integer.parseInt(each[i]));
                        } catch (NumberFormatException e) {
                            send(ex, 400, "text/plain; charset=utf-8", "from must be step numbers, one a robot: " + pair);
                            return;
                        }
                    }
                }
            }
        }
        JsonObject answer = new JsonObject();
        answer.addProperty("status", status);
        JsonArray parts = new JsonArray(fleet.size());
        for (int i = 0; i < fleet.size(); i++) {
            ReplayData data = fleet.get(i).data();
            parts.add(data.toJson(from[i] > data.size() ? 0 : from[i])); // past its end: a new run, start over
        }
        answer.add("robots", parts);
        send(ex, 200, "application/json; charset=utf-8", GSON.toJson(answer));
    }

    private static boolean allowed(HttpExchange ex) throws IOException {
        if (!"GET".equals(ex.getRequestMethod()) && !"HEAD".equals(ex.getRequestMethod())) {
            ex.getResponseHeaders().set("Allow", "GET, HEAD");
            send(ex, 405, "text/plain; charset=utf-8", "read only: GET");
            return false;
        }
        return true;
    }

    private static void send(HttpExchange ex, int code, String type, String body) throws IOException {
        byte[] bytes = body.getBytes(StandardCharsets.UTF_8);
        ex.getResponseHeaders().set("Content-Type", type);
        ex.getResponseHeaders().set("Cache-Control", "no-store");
        boolean head = "HEAD".equals(ex.getRequestMethod());
        ex.sendResponseHeaders(code, head ? -1 : bytes.length);
        if (!head) {
            try (OutputStream out = ex.getResponseBody()) {
                out.write(bytes);
            }
        }
        ex.close();
    }

    @Override
    public void close() {
        server.stop(0);
        threads.shutdownNow();
    }
}
