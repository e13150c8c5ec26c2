package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.proactiverobotics.app.generate.Solvability;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.map.MapServerWriter;
import org.proactiverobotics.sim2d.map.OccupancyGrid;
import org.proactiverobotics.sim2d.map.WorldRaster;

/**
 * {@code import-map} (issue 33, docs/maps.md): maps the test makes itself become worlds with a seeded,
 * solvable mission; a world rasterised and imported back keeps its walls; bad maps exit 2 naming the
 * file and the problem, writing nothing; an imported floor runs a mission to the end.
 */
class ImportMapCommandTest extends CommandLineTest {

    @TempDir
    Path tmp;

    /**
     * Two rooms of a 6 x 4.5 m floor at 0.05 m, a wall between them with a 0.9 m door, 0.15 m walls
     * round them, unknown (205) outside: the picture map_server would save.
     */
    static Path twoRooms(Path dir) throws IOException {
        int w = 140;
        int h = 110;
        int[] px = new int[w * h];
        java.util.Arrays.fill(px, 205);
        fill(px, w, 10, 10, 130, 100, 0);
        fill(px, w, 13, 13, 127, 97, 254);
        fill(px, w, 68, 13, 71, 97, 0); // the wall between the rooms
        fill(px, w, 68, 40, 71, 58, 254); // its door, 18 cells
        fill(px, w, 30, 60, 40, 70, 0); // a cupboard
        byte[] header = String.format(Locale.ROOT, "P5\n%d %d\n255\n", w, h).getBytes(StandardCharsets.US_ASCII);
        byte[] bytes = new byte[header.length + px.length];
        System.arraycopy(header, 0, bytes, 0, header.length);
        for (int k = 0; k < px.length; k++) {
            bytes[header.length + k] = (byte) px[k];
        }
        Files.write(dir.resolve("rooms.pgm"), bytes);
        return Files.writeString(dir.resolve("rooms.yaml"), "image: rooms.pgm\nresolution: 0.05\norigin: [-2.0, 1.5, 0.0]\n"
                + "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n");
    }

    private static void fill(int[] px, int w, int x0, int y0, int x1, int y1, int v) {
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                px[y * w + x] = v;
            }
        }
    }

    @Test
    void aMapServerMapBecomesAValidSolvableWorldAndTheCommandSaysWhatCameOut() throws Exception {
        Path map = twoRooms(tmp);
        Path world = tmp.resolve("out").resolve("rooms.json");
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString(), "--checkpoints", "2"))
                .as(err.toString()).isZero();
        String said = out.toString();
        assertThat(said).contains(map + ": 7.0 x 5.5 m (140 x 110 cells of 0.05 m), free floor ")
                .contains("mission: start (").contains("2 checkpoints").contains("wrote " + world + " (boxes inline)");
        assertThat(said).doesNotContain("warning");
        WorldSpec w = WorldFiles.load(world);
        assertThat(w.name()).isEqualTo("rooms");
        assertThat(w.arena()).isEqualTo(WorldSpec.Arena.rectangle(7.0, 5.5, 1.5, 4.25));
        assertThat(w.checkpoints()).hasSize(2);
        Solvability plan = Solvability.of(w);
        assertThat(plan.solvable()).isTrue();
        // one charge lasts three times the planned tour: the robot explores a floor it does not know
        assertThat(plan.recharges()).isZero();
        assertThat(w.battery().drainPerMeter() * 3 * plan.lengthM()).isLessThanOrEqualTo(100.0);
        // the start in one room, both checkpoints in the other (the door closes the rooms apart)
        double wallX = -2.0 + 69.5 * 0.05;
        assertThat(w.checkpoints()).allMatch(c -> Math.signum(c.x() - wallX) != Math.signum(w.robot().x() - wallX)
                || Math.signum(c.x() - wallX) == Math.signum(w.checkpoints().get(0).x() - wallX));
        assertThat(Math.hypot(w.rechargeStation().x() - w.robot().x(), w.rechargeStation().y() - w.robot().y()))
                .as("the station near the start").isLessThan(2.0);
        assertThat(run("validate", "--world", world.toString())).isZero();
    }

    @Test
    void theSameMapAndSeedGiveTheSameWorldAnotherSeedAnotherMission() throws Exception {
        Path map = twoRooms(tmp);
        for (String name : new String[] {"a", "b"}) {
            assertThat(run("import-map", "--map", map.toString(), "--out", tmp.resolve(name + ".json").toString(), "--seed", "5"))
                    .isZero();
        }
        assertThat(run("import-map", "--map", map.toString(), "--out", tmp.resolve("c.json").toString(), "--seed", "6")).isZero();
        assertThat(Files.readString(tmp.resolve("a.json"))).isEqualTo(Files.readString(tmp.resolve("b.json")));
        WorldSpec a = WorldFiles.load(tmp.resolve("a.json"));
        WorldSpec c = WorldFiles.load(tmp.resolve("c.json"));
        assertThat(c.obstacles()).isEqualTo(a.obstacles());
        assertThat(c.robot().x() != a.robot().x() || c.robot().y() != a.robot().y() || !c.checkpoints().equals(a.checkpoints()))
                .as("another seed, another mission").isTrue();
    }

    @Test
    void aWorldRasterisedToAPgmAndImportedBackHasItsWallsWhereTheyWereToACell() throws Exception {
        WorldSpec rooms = new WorldGenerator(WorldGenerator.Kind.ROOMS).world(4, 1);
        // the rooms' block: outer walls' faces at +-3.4 m; 0.05 m cells
        OccupancyGrid grid = WorldRaster.of(rooms, 0.05, -3.4, -3.4, 136, 136);
        Path yaml = tmp.resolve("raster.yaml");
        MapServerWriter.write(grid, yaml);
        Path world = tmp.resolve("back.json");
        assertThat(run("import-map", "--map", yaml.toString(), "--out", world.toString())).as(err.toString()).isZero();
        WorldSpec back = WorldFiles.load(world);
        int differ = 0;
        for (int j = 0; j < 136; j++) {
            for (int i = 0; i < 136; i++) {
                double x = -3.4 + (i + 0.5) * 0.05;
                double y = -3.4 + (j + 0.5) * 0.05;
                if (WorldRaster.blocked(rooms, x, y) != WorldRaster.blocked(back, x, y)) {
                    differ++;
                }
            }
        }
        assertThat(differ).as("cells whose centre is a wall in one world and floor in the other").isZero();
        assertThat(grid.freeCells()).isLessThan(136 * 136).isGreaterThan(136 * 136 / 2);
        // and every wall of the original lies under the imported boxes, to a cell (0.05 m) at its rim
        for (WorldSpec.Obstacle o : rooms.obstacles()) {
            assertThat(back.obstacles().stream().mapToDouble(b -> b.distanceTo(o.x(), o.y())).min().orElseThrow())
                    .as("the centre of %s", o).isZero();
        }
        assertThat(back.obstacles().size()).as("merged: fewer boxes than wall cells").isLessThan(rooms.obstacles().size() * 4);
    }

    @Test
    void aMovingAiMapIsReadWithItsCellSize() throws Exception {
        StringBuilder map = new StringBuilder("type octile\nheight 12\nwidth 16\nmap\n");
        for (int r = 0; r < 12; r++) {
            for (int c = 0; c < 16; c++) {
                boolean wall = r == 0 || c == 0 || r == 11 || c == 15 || (c == 8 && r != 3 && r != 4);
                map.append(wall ? (r % 2 == 0 ? '@' : 'T') : (c % 3 == 0 ? 'G' : c % 3 == 1 ? 'S' : '.'));
            }
            map.append('\n');
        }
        Path file = Files.writeString(tmp.resolve("grid.map"), map);
        Path world = tmp.resolve("grid.json");
        assertThat(run("import-map", "--map", file.toString(), "--cell-m", "0.4", "--out", world.toString(), "--checkpoints", "2"))
                .as(err.toString()).isZero();
        assertThat(out.toString()).contains("6.4 x 4.8 m (16 x 12 cells of 0.4 m)");
        WorldSpec w = WorldFiles.load(world);
        assertThat(w.arena()).isEqualTo(WorldSpec.Arena.rectangle(6.4, 4.8, 3.2, 2.4));
        assertThat(Solvability.of(w).solvable()).isTrue();
    }

    @Test
    void referenceMapNamesTheMapAndReadsBackToTheSameWorld() throws Exception {
        Path maps = Files.createDirectories(tmp.resolve("maps"));
        Path map = twoRooms(maps);
        Path inline = tmp.resolve("inline").resolve("inline.json");
        Path named = tmp.resolve("worlds").resolve("named.json");
        assertThat(run("import-map", "--map", map.toString(), "--out", inline.toString())).isZero();
        // the world's folder does not exist yet: the map's relative name is read back all the same
        assertThat(run("import-map", "--map", map.toString(), "--out", named.toString(), "--reference-map")).as(err.toString())
                .isZero();
        JsonObject json = JsonParser.parseString(Files.readString(named)).getAsJsonObject();
        assertThat(json.getAsJsonObject("map").get("file").getAsString()).isEqualTo("../maps/rooms.yaml");
        assertThat(json.has("arena")).isFalse();
        assertThat(json.has("obstacles")).isFalse();
        assertThat(WorldFiles.load(named)).isEqualTo(WorldFiles.load(inline));
        assertThat(run("validate", "--world", named.toString())).isZero();
        assertThat(out.toString()).contains("rooms: valid (");
    }

    @Test
    void aPictureAloneIsReadAsMapServerReadsItAtTheResolutionGivenAndCanBeNamedByTheWorld() throws Exception {
        Path maps = Files.createDirectories(tmp.resolve("maps"));
        Path yaml = twoRooms(maps);
        Path picture = maps.resolve("rooms.pgm");
        Path viaYaml = tmp.resolve("yaml.json");
        Path alone = tmp.resolve("alone.json");
        assertThat(run("import-map", "--map", yaml.toString(), "--out", viaYaml.toString(), "--seed", "3")).isZero();
        assertThat(run("import-map", "--map", picture.toString(), "--out", alone.toString(), "--seed", "3", "--cell-m", "0.05"))
                .as(err.toString()).isZero();
        assertThat(out.toString()).contains(picture + ": 7.0 x 5.5 m (140 x 110 cells of 0.05 m)");
        WorldSpec a = WorldFiles.load(alone);
        WorldSpec y = WorldFiles.load(viaYaml);
        // the YAML puts the lower-left corner at (-2.0, 1.5); alone it lies at (0, 0): the same walls, moved
        assertThat(a.arena()).isEqualTo(WorldSpec.Arena.rectangle(7.0, 5.5, 3.5, 2.75));
        assertThat(a.obstacles()).hasSameSizeAs(y.obstacles());
        for (int k = 0; k < a.obstacles().size(); k++) {
            WorldSpec.Obstacle o = a.obstacles().get(k);
            WorldSpec.Obstacle p = y.obstacles().get(k);
            assertThat(o.x() - 2.0).isCloseTo(p.x(), org.assertj.core.data.Offset.offset(1e-9));
            assertThat(o.y() + 1.5).isCloseTo(p.y(), org.assertj.core.data.Offset.offset(1e-9));
        }
        assertThat(Solvability.of(a).solvable()).isTrue();

        Path named = tmp.resolve("worlds").resolve("named.json");
        assertThat(run("import-map", "--map", picture.toString(), "--out", named.toString(), "--seed", "3", "--cell-m", "0.05",
                "--reference-map")).as(err.toString()).isZero();
        JsonObject map = JsonParser.parseString(Files.readString(named)).getAsJsonObject().getAsJsonObject("map");
        assertThat(map.get("file").getAsString()).isEqualTo("../maps/rooms.pgm");
        assertThat(map.get("cellM").getAsDouble()).isEqualTo(0.05);
        assertThat(WorldFiles.load(named)).isEqualTo(a);

        // a world naming a picture without its scale is refused, naming the key
        Files.writeString(named, Files.readString(named).replaceAll(",\\s*\"cellM\": 0.05", ""));
        assertThat(run("validate", "--world", named.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("map.cellM: a picture alone has no scale: give cellM (metres a pixel)");
    }

    static Stream<Arguments> badMaps() {
        return Stream.of(
                Arguments.of("missing image", "image: gone.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", null,
                        "gone.pgm: no such image file"),
                Arguments.of("wrong magic number", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", "BM....",
                        "m.pgm: wrong magic number: neither a PGM (P2, P5) nor a PNG image"),
                Arguments.of("occupied_thresh out of range", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                        + "occupied_thresh: 1.2\n", "P2\n2 2\n255\n0 0 0 0\n", "m.yaml: occupied_thresh: must be from 0 to 1, got 1.2"),
                Arguments.of("free_thresh out of range", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                        + "free_thresh: -1\n", "P2\n2 2\n255\n0 0 0 0\n", "m.yaml: free_thresh: must be from 0 to 1, got -1.0"),
                Arguments.of("PGM smaller than its header", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n",
                        "P5\n3 2\n255\nabcde", "m.pgm: the header says 3 x 2 pixels (6 bytes) but the file holds 5 bytes of pixels"),
                Arguments.of("no free cell the robot fits in", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n",
                        "P2\n4 4\n255\n0 0 0 0\n0 254 254 0\n0 254 254 0\n0 0 0 0\n",
                        "m.yaml: no free cell the robot fits in for a robot of radius 0.12 m (its centre keeps 0.17 m from every wall)"),
                Arguments.of("a rotated origin", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 1.57]\n", "P2\n1 1\n255\n0\n",
                        "m.yaml: origin: the yaw must be 0 (a rotated map is not read), got 1.57"),
                Arguments.of("an unknown key", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nthreshold: 3\n",
                        "P2\n1 1\n255\n0\n", "m.yaml: unknown key threshold"),
                Arguments.of("an unknown mode", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nmode: binary\n",
                        "P2\n1 1\n255\n0\n", "m.yaml: mode: must be trinary, scale or raw, got binary"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badMaps")
    void aBadMapExitsTwoNamingTheFileAndTheProblemAndWritesNothing(String what, String yaml, String image, String problem)
            throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("bad"));
        Path map = Files.writeString(dir.resolve("m.yaml"), yaml);
        if (image != null) {
            Files.writeString(dir.resolve("m.pgm"), image, StandardCharsets.ISO_8859_1);
        }
        Path world = tmp.resolve("out").resolve("w.json");
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString())).isEqualTo(2);
        assertThat(err.toString().lines().toList()).singleElement().asString().contains(problem).doesNotContain("Exception");
        assertThat(tmp.resolve("out")).doesNotExist();
        assertThat(out.toString()).isEmpty();
    }

    @Test
    void badOptionsExitTwoAndWriteNothing() throws Exception {
        Path map = twoRooms(tmp);
        Path world = tmp.resolve("w.json");
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString(), "--cell-m", "0.5")).isEqualTo(2);
        assertThat(err.toString()).contains("--cell-m is for Moving AI maps (.map) and pictures alone (.pgm, .png)");
        assertThat(run("import-map", "--map", tmp.resolve("rooms.pgm").toString(), "--out", world.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("rooms.pgm: a picture alone has no scale: give --cell-m (metres a pixel");
        for (String cell : new String[] {null, "0.05"}) {
            String[] args = cell == null ? new String[] {"import-map", "--map", tmp.resolve("rooms.bmp").toString(), "--out", world.toString()}
                    : new String[] {"import-map", "--map", tmp.resolve("rooms.bmp").toString(), "--out", world.toString(), "--cell-m", cell};
            err.getBuffer().setLength(0);
            assertThat(run(args)).isEqualTo(2);
            assertThat(err.toString()).as("with --cell-m %s", cell).contains("rooms.bmp: not a map this reads: give a ROS map_server"
                    + " YAML (.yaml), a Moving AI map (.map), or a picture (.pgm, .png) with --cell-m");
        }
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString(), "--robot-radius", "0.5")).isEqualTo(2);
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString(), "--checkpoints", "0")).isEqualTo(2);
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString(), "--name", "my floor")).isEqualTo(2);
        assertThat(err.toString()).contains("--name must be letters, digits, '-' or '_': my floor");
        assertThat(world).doesNotExist();
        Files.writeString(world, "{}");
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("exists: give --force to overwrite it");
        assertThat(Files.readString(world)).isEqualTo("{}");
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString(), "--force", "--name", "floor-2")).isZero();
        assertThat(WorldFiles.load(world).name()).isEqualTo("floor-2");
    }

    @Test
    void aFreeThresholdThatOpensTheOutsideIsWarnedAbout() throws Exception {
        Path map = twoRooms(tmp);
        Files.writeString(map, Files.readString(map).replace("free_thresh: 0.196", "free_thresh: 0.25"));
        assertThat(run("import-map", "--map", map.toString(), "--out", tmp.resolve("w.json").toString())).isZero();
        assertThat(out.toString()).contains("warning: free_thresh 0.25 reads map_server's unknown grey (205, p = 0.196) as free")
                .contains("warning: 496 free cells lie on the map's edge");
    }

    @Test
    void anImportedFloorRunsAMissionToTheEndAndTheWorldNamingTheMapToo() throws Exception {
        Path map = twoRooms(tmp);
        Path world = tmp.resolve("rooms.json");
        assertThat(run("import-map", "--map", map.toString(), "--out", world.toString(), "--checkpoints", "2", "--reference-map"))
                .as(err.toString()).isZero();
        Path runDir = tmp.resolve("run");
        assertThat(run("run", "--world", world.toString(), "--link", "direct", "--quiet", "--out", runDir.toString()))
                .as(err.toString() + out).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(runDir.resolve("report.json"))).getAsJsonObject();
        assertThat(report.get("outcome").getAsString()).isEqualTo("MISSION_ACCOMPLISHED");
        assertThat(report.get("checkpointsReached").getAsInt()).isEqualTo(2);
        assertThat(report.get("collisions").getAsInt()).isZero();
        assertThat(Files.readString(runDir.resolve("trajectory.svg"))).contains("<g id=\"arena\"><rect ");
        assertThat(Files.readString(runDir.resolve("replay.html"))).contains("\"arenaRect\"");
    }
}
