package org.proactiverobotics.app.foxglove;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.proactiverobotics.app.replay.TraceEvent;
import org.proactiverobotics.app.replay.TraceStep;
import org.proactiverobotics.mcap.McapWriter;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Writes run.mcap (docs/foxglove.md): each iteration's step, the same one trace.jsonl gets, as
 * JSON messages on the Foxglove channels, log time = simulated time. /world once at time 0; per
 * step /tf (world → base_link, true pose), /pose (true pose), /pose_estimate (the engine's belief,
 * when it changed), /scan (the rays the engine read), /decision, /battery, one /events message per
 * event or reason, and /map (the engine's occupancy map) when it changed, at most once per
 * simulated second. The same steps give the same bytes. A write error does not stop the mission:
 * the first one is reported by {@link #close()}.
 * <p>
 * A world of several robots ({@link #openFleet}) gets one file with one /world and, per robot, the same topics
 * under {@code /robot/ID} ({@code /robot/2/tf}, {@code /robot/2/scan}, ...) and its body in the frame
 * {@code robot_ID/base_link}; each robot's recorder writes its own steps.
 */
public final class McapRecorder implements AutoCloseable {

    /** The file's name in a run's folder. */
    public static final String FILE_NAME = "run.mcap";
    /** The Header's library field: fixed, so that equal runs give equal bytes. */
    static final String LIBRARY = "proactive-robotics mcap 1";
    /** The engine's map is written at most this often, ms of simulated time. */
    static final long MAP_PERIOD_MS = 1000;

    private final McapWriter writer;
    /** Whether closing this recorder ends the file (one robot), or only its robot's part (a fleet's). */
    private final boolean ownsFile;
    /** The robot's body frame: {@code base_link}, or {@code robot_ID/base_link} in a fleet. */
    private final String baseLink;
    private final JsonText j = new JsonText();
    private final ScanLayout scan;
    private final double bodyM;
    private final MapGrid map = new MapGrid();
    private final BeliefFields beliefs = new BeliefFields();
    private final double[] belief = new double[3];
    private final int tf;
    private final int pose;
    private final int poseEstimate;
    private final int scanChannel;
    private final int mapChannel;
    private final int decision;
    private final int battery;
    private final int events;
    private boolean mapPending;
    private long lastMapMs = Long.MIN_VALUE;
    private long lastStepMs;
    private final Map<String, Integer> schemas;
    private IOException failure;

    private McapRecorder(McapWriter writer, WorldSpec world) throws IOException {
        this(writer, new TreeMap<>(), world.robot(), "", "base_link", true, world);
    }

    /**
     * @param schemas  the file's schemas by name (shared by a fleet's recorders)
     * @param robot    the robot recorded
     * @param prefix   its topics' prefix ("" or {@code /robot/ID})
     * @param baseLink its body's frame
     * @param ownsFile whether closing it ends the file
     * @param world    the world to write on /world first, or null (a fleet's file has written it)
     */
    private McapRecorder(McapWriter writer, Map<String, Integer> schemas, WorldSpec.Robot robot, String prefix,
                         String baseLink, boolean ownsFile, WorldSpec world) throws IOException {
        this.writer = writer;
        this.schemas = schemas;
        this.ownsFile = ownsFile;
        this.baseLink = baseLink;
        this.scan = ScanLayout.of(robot.sensorAnglesDeg());
        this.bodyM = robot.radiusM();
        int sceneChannel = world == null ? -1 : channel("/world", "foxglove.SceneUpdate");
        this.tf = channel(prefix + "/tf", "foxglove.FrameTransform");
        this.pose = channel(prefix + "/pose", "foxglove.PoseInFrame");
        this.poseEstimate = channel(prefix + "/pose_estimate", "foxglove.PoseInFrame");
        this.scanChannel = channel(prefix + "/scan", "foxglove.LaserScan");
        this.mapChannel = channel(prefix + "/map", "foxglove.Grid");
        this.decision = channel(prefix + "/decision", "proactive.Decision");
        this.battery = channel(prefix + "/battery", "proactive.Battery");
        this.events = channel(prefix + "/events", "foxglove.Log");
        if (world != null) {
            Scene.write(j, world);
            emit(sceneChannel, 0);
        }
    }

    /**
     * run.mcap of a world with several robots: one file, /world with every robot, and a recorder per robot whose
     * topics are under {@code /robot/ID}.
     */
    public static final class Fleet implements AutoCloseable {

        private final McapWriter writer;
        private final List<McapRecorder> robots = new ArrayList<>();

        private Fleet(McapWriter writer, WorldSpec world) throws IOException {
            this.writer = writer;
            Map<String, Integer> schemas = new TreeMap<>();
            int sceneChannel = writer.channel("/world", schemas.computeIfAbsent("foxglove.SceneUpdate",
                    n -> writer.schema(n, "jsonschema", schemaBytes(n))), "json", Map.of());
            for (WorldSpec.RobotEntry r : world.robots()) {
                robots.add(new McapRecorder(writer, schemas, r.robot(), "/robot/" + r.id(), Scene.baseLink(r.id()),
                        false, null));
            }
            JsonText j = new JsonText();
            Scene.writeFleet(j, world);
            writer.message(sceneChannel, 0, j.bytes(), 0, j.length());
        }

        /**
         * @param index the robot's position in the world's robots
         * @return its recorder
         */
        public McapRecorder robot(int index) {
            return robots.get(index);
        }

        /**
         * Writes each robot's map still waiting, then the file's end.
         *
         * @throws IOException the first write error of any robot, or of the end
         */
        @Override
        public void close() throws IOException {
            IOException first = null;
            for (McapRecorder r : robots) {
                try {
                    r.close();
                } catch (IOException e) {
                    first = first == null ? e : first;
                }
            }
            try {
                writer.close();
            } catch (IOException e) {
                first = first == null ? new IOException("writing " + FILE_NAME + ": " + e.getMessage(), e) : first;
            }
            if (first != null) {
                throw first;
            }
        }
    }

    /**
     * Creates the file and writes its header, schemas, channels and /world.
     *
     * @param file  run.mcap
     * @param world the world the mission runs in
     * @return the recorder
     * @throws IOException when the file cannot be written
     */
    public static McapRecorder open(Path file, WorldSpec world) throws IOException {
        McapWriter writer = new McapWriter(new BufferedOutputStream(Files.newOutputStream(file), 1 << 16), "", LIBRARY,
                McapWriter.DEFAULT_CHUNK_SIZE_BYTES);
        try {
            return new McapRecorder(writer, world);
        } catch (IOException | RuntimeException e) {
            writer.close();
            throw e;
        }
    }

    /**
     * Creates the file of a world with several robots and writes its header, schemas, every robot's channels and
     * /world.
     *
     * @param file  run.mcap
     * @param world the world, with every robot
     * @return the fleet's recorders
     * @throws IOException when the file cannot be written
     */
    public static Fleet openFleet(Path file, WorldSpec world) throws IOException {
        FleetLayout.write(file.resolveSibling(FleetLayout.FILE_NAME), world); // the shipped layout names one robot's topics
        McapWriter writer = new McapWriter(new BufferedOutputStream(Files.newOutputStream(file), 1 << 16), "", LIBRARY,
                McapWriter.DEFAULT_CHUNK_SIZE_BYTES);
        try {
            return new Fleet(writer, world);
        } catch (IOException | RuntimeException e) {
            writer.close();
            throw e;
        }
    }

    private int channel(String topic, String schema) {
        return writer.channel(topic, schemaId(schema), "json", Map.of());
    }

    private int schemaId(String name) {
        return schemas.computeIfAbsent(name, n -> writer.schema(n, "jsonschema", schemaBytes(n)));
    }

    private static byte[] schemaBytes(String name) {
        try (InputStream in = McapRecorder.class.getResourceAsStream(name + ".json")) {
            if (in == null) {
                throw new IllegalStateException("the jar lacks the JSON schema " + name);
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Writes one iteration's messages. */
    public void record(TraceStep s) {
        if (failure != null) {
            return;
        }
        try {
            write(s);
        } catch (IOException e) {
            failure = e;
        }
    }

    private void write(TraceStep s) throws IOException {
        long t = s.simTimeMs();
        lastStepMs = t;
        j.begin().open().name("timestamp").time(t).name("parent_frame_id").string("world")
                .name("child_frame_id").string(baseLink).name("translation");
        Scene.vector(j, s.xM(), s.yM(), 0);
        j.name("rotation");
        Scene.quaternion(j, s.headingRad());
        j.close().end();
        emit(tf, t);

        poseInFrame(t, s.xM(), s.yM(), s.headingRad());
        emit(pose, t);

        if (beliefs.newPose(s, belief)) {
            poseInFrame(t, belief[0], belief[1], belief[2]);
            emit(poseEstimate, t);
        }

        if (s.scanM() != null) {
            writeScan(t, s.scanM());
            emit(scanChannel, t);
        }

        writeDecision(s);
        emit(decision, t);

        j.begin().open().name("timestamp").time(t).name("battery_pct").number(s.batteryPct(), 2).name("seen_battery_pct");
        if (Double.isNaN(s.seenBattery())) {
            j.nullValue();
        } else {
            j.number(s.seenBattery(), 2);
        }
        j.name("charging").bool(s.charging()).name("left_wheel_mps").number(s.leftMps(), 3)
                .name("right_wheel_mps").number(s.rightMps(), 3).close().end();
        emit(battery, t);

        for (TraceEvent e : s.events()) {
            log(t, level(e.type()), e.toJson().toString());
        }
        String reason = beliefs.reason(s);
        if (reason != null) {
            log(t, 3, reason);
        }

        int[] delta = beliefs.mapDelta(s);
        if (delta != null && map.apply(delta)) {
            mapPending = true;
        }
        if (mapPending && (lastMapMs == Long.MIN_VALUE || t - lastMapMs >= MAP_PERIOD_MS)) {
            writeMap(t);
        }
    }

    private void writeMap(long t) throws IOException {
        map.write(j, t);
        emit(mapChannel, t);
        mapPending = false;
        lastMapMs = t;
    }

    private void poseInFrame(long t, double x, double y, double heading) {
        j.begin().open().name("timestamp").time(t).name("frame_id").string("world").name("pose");
        Scene.pose(j, x, y, 0, heading);
        j.close().end();
    }

    private void writeScan(long t, double[] rays) {
        j.begin().open().name("timestamp").time(t).name("frame_id").string(baseLink).name("pose");
        Scene.pose(j, 0, 0, 0.05, 0);
        j.name("start_angle").number(scan.startRad, 6).name("end_angle").number(scan.endRad, 6);
        j.name("ranges").openArray();
        int ray = 0;
        for (int b = 0; b < scan.bearings; b++) {
            if (ray < rays.length && ray < scan.slot.length && scan.slot[ray] == b && Double.isFinite(rays[ray])) {
                j.number(bodyM + rays[ray], 3);
                ray++;
            } else {
                if (ray < scan.slot.length && scan.slot[ray] == b) {
                    ray++; // a ray without a reading
                }
                j.integer(0);
            }
        }
        j.closeArray().name("intensities").openArray(); // none: a bearing without a ray reads 0
        j.closeArray().close().end();
    }

    private void writeDecision(TraceStep s) {
        j.begin().open().name("timestamp").time(s.simTimeMs()).name("iteration").integer(s.iteration());
        j.name("suggestions");
        if (s.suggestions() == null) {
            j.nullValue();
        } else {
            j.openArray();
            for (Map.Entry<String, String> e : s.suggestions().entrySet()) {
                j.open().name("scenario").string(e.getKey()).name("command").string(e.getValue()).close();
            }
            j.closeArray();
        }
        j.name("priorities");
        if (s.priorities() == null) {
            j.nullValue();
        } else {
            j.openArray();
            for (Map.Entry<String, Integer> e : s.priorities().entrySet()) {
                j.open().name("scenario").string(e.getKey()).name("priority").integer(e.getValue()).close();
            }
            j.closeArray();
        }
        j.name("winner").string(s.winner()).name("command").string(s.command()).close().end();
    }

    private void log(long t, int level, String message) throws IOException {
        j.begin().open().name("timestamp").time(t).name("level").integer(level).name("message").string(message)
                .name("name").string("proactive").name("file").string("").name("line").integer(0).close().end();
        emit(events, t);
    }

    /** foxglove.Log levels: 2 info, 3 warning, 4 error. */
    private static int level(String type) {
        return switch (type) {
            case TraceEvent.RULE_FAILURE -> 4;
            case TraceEvent.COLLISION, TraceEvent.FAIL_SAFE, TraceEvent.CHECKPOINT_UNREACHABLE -> 3;
            default -> 2;
        };
    }

    private void emit(int channel, long simTimeMs) throws IOException {
        writer.message(channel, simTimeMs * 1_000_000L, j.bytes(), 0, j.length());
    }

    /**
     * Writes a map still waiting for its turn, then the file's end (summary, footer).
     *
     * @throws IOException the first write error of the run, or of the end
     */
    @Override
    public void close() throws IOException {
        try {
            if (failure == null && mapPending) {
                writeMap(lastStepMs);
            }
        } catch (IOException e) {
            failure = e;
        }
        try {
            if (ownsFile) {
                writer.close();
            }
        } catch (IOException e) {
            if (failure == null) {
                failure = e;
            }
        }
        if (failure != null) {
            throw new IOException("writing " + FILE_NAME + ": " + failure.getMessage(), failure);
        }
    }
}
