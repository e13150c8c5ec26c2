package org.proactiverobotics.app.sweep;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonParseException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.sim2d.JsonSyntax;

/**
 * sweep.json: what a sweep (or one shard of it) was, written before its first mission, so that
 * {@code sweep merge} can tell shards of one sweep from shards of another. The definition is a
 * SHA-256 over every combination of the whole sweep (each world's file with its seed, strategy,
 * noise level, seed), the link, the scenario plug-ins' jars and the program's version: shards
 * agree on it exactly when they were cut from the same sweep.
 *
 * @param definition    the sweep's definition, hex SHA-256
 * @param shard         this slice's index, from 0
 * @param shards        how many slices the sweep was cut into
 * @param missions      missions in the whole sweep
 * @param shardMissions missions in this slice
 * @param link          {@code jdbc} or {@code direct}
 * @param version       the program that ran it
 */
public record SweepManifest(String definition, int shard, int shards, int missions, int shardMissions, String link,
                            String version) {

    /** The file's name in a sweep's folder. */
    public static final String FILE = "sweep.json";

    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().create();

    /**
     * Describes a sweep (its definition) and the slice of it this process runs.
     *
     * @param all      every mission of the whole sweep, in order
     * @param shard    the slice this process runs
     * @param link     the link the missions run on
     * @param plugins  the scenario plug-ins' jars
     * @param version  the program's version
     * @return the manifest
     * @throws IOException when a plug-in's jar cannot be read
     */
    public static SweepManifest of(List<SweepMission> all, Shard shard, MissionOptions.Link link, List<Path> plugins,
                                   String version) throws IOException {
        MessageDigest sha = sha256();
        StringBuilder text = new StringBuilder("link ").append(link).append('\n').append("version ").append(version).append('\n');
        for (Path jar : plugins) {
            try (InputStream in = Files.newInputStream(jar)) {
                text.append("plugin ").append(HexFormat.of().formatHex(sha256().digest(in.readAllBytes()))).append('\n');
            }
        }
        int inShard = 0;
        for (SweepMission m : all) {
            text.append(m.index()).append('\t').append(m.folder()).append('\t')
                    .append(HexFormat.of().formatHex(sha256().digest(WorldJson.of(m.world()).getBytes(StandardCharsets.UTF_8))))
                    .append('\t').append(canonical(m.strategy().priorities())).append('\t')
                    .append(canonical(m.strategy().timeoutsMs())).append('\n');
            if (shard.contains(m.index())) {
                inShard++;
            }
        }
        String definition = HexFormat.of().formatHex(sha.digest(text.toString().getBytes(StandardCharsets.UTF_8)));
        return new SweepManifest(definition, shard.index(), shard.count(), all.size(), inShard,
                link == MissionOptions.Link.DIRECT ? "direct" : "jdbc", version);
    }

    /** @return the slice this manifest describes */
    public Shard slice() {
        return new Shard(shard, shards);
    }

    /**
     * Writes sweep.json into a sweep's folder.
     *
     * @param dir the folder
     * @throws IOException when it cannot be written
     */
    public void write(Path dir) throws IOException {
        Files.writeString(dir.resolve(FILE), GSON.toJson(this) + "\n", StandardCharsets.UTF_8);
    }

    /**
     * Reads the sweep.json of a sweep's folder.
     *
     * @param dir a sweep's folder
     * @return its sweep.json
     * @throws IOException when it is missing or cannot be read
     * @throws IllegalArgumentException when it is not a sweep.json (naming the file)
     */
    public static SweepManifest read(Path dir) throws IOException {
        Path file = dir.resolve(FILE);
        SweepManifest m;
        try {
            m = GSON.fromJson(Files.readString(file, StandardCharsets.UTF_8), SweepManifest.class);
        } catch (JsonParseException e) {
            throw new IllegalArgumentException(file + " is not a sweep's sweep.json: malformed JSON: " + JsonSyntax.describe(e));
        }
        if (m == null || m.definition() == null || m.shards() < 1 || m.shard() < 0 || m.shard() >= m.shards()
                || m.missions() < 0) {
            throw new IllegalArgumentException(file + " is not a sweep's sweep.json (definition, shard and shards needed)");
        }
        return m;
    }

    private static String canonical(Map<String, ? extends Number> map) {
        return new TreeMap<>(map).toString();
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JVM has SHA-256", e);
        }
    }
}
