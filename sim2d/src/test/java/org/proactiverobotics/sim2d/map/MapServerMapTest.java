package org.proactiverobotics.sim2d.map;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** map_server maps read as map_server reads them: every YAML field, P2 and P5, PNG, the three modes. */
class MapServerMapTest {

    @TempDir
    Path dir;

    /**
     * A 4 x 2 picture across the trinary thresholds: p = (255 - v) / 255, free below free_thresh 0.196
     * (v 206 and up), occupied above occupied_thresh 0.65 (v 89 and down), unknown between (205 is
     * map_server's unknown grey); only free cells are floor.
     */
    private static final int[] ACROSS = {
        254, 206, 205, 0,
        100, 89, 90, 255,
    };

    @Test
    void everyFieldOfTheYamlIsReadOriginResolutionAndThresholds() throws IOException {
        MapFixtures.p5(dir.resolve("m.pgm"), 4, 2, 255, ACROSS);
        Path yaml = MapFixtures.yaml(dir.resolve("m.yaml"), "image: m.pgm", "resolution: 0.1", "origin: [-3.5, 2.0, 0.0]",
                "negate: 0", "occupied_thresh: 0.65", "free_thresh: 0.196", "mode: trinary");
        MapReading map = MapServerMap.read(yaml);
        OccupancyGrid g = map.grid();
        assertThat(g.columns()).isEqualTo(4);
        assertThat(g.rows()).isEqualTo(2);
        assertThat(g.cellM()).isEqualTo(0.1);
        assertThat(g.originX()).isEqualTo(-3.5);
        assertThat(g.originY()).isEqualTo(2.0);
        assertThat(g.widthM()).isEqualTo(0.4, org.assertj.core.api.Assertions.within(1e-12));
        // the picture's top row is the map's top (row 1): 254 and 206 free; 205 unknown, 0 occupied
        assertThat(MapFixtures.picture(g)).isEqualTo("""
                ..##
                ###.
                """);
        assertThat(map.notes()).isEmpty();
    }

    @Test
    void theThresholdsDecideAndAFreeThresholdAboveTheUnknownGreyIsNamed() throws IOException {
        MapFixtures.p5(dir.resolve("m.pgm"), 4, 2, 255, ACROSS);
        // free below p 0.25: v 192 and up, so 205 (unknown when saved) becomes floor
        Path yaml = MapFixtures.yaml(dir.resolve("m.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]",
                "negate: 0", "occupied_thresh: 0.9", "free_thresh: 0.25");
        MapReading map = MapServerMap.read(yaml);
        assertThat(MapFixtures.picture(map.grid())).isEqualTo("""
                ...#
                ###.
                """);
        assertThat(map.notes()).singleElement().asString().contains("free_thresh 0.25 reads map_server's unknown grey (205");
    }

    @Test
    void negateTurnsTheShadesOver() throws IOException {
        MapFixtures.p5(dir.resolve("m.pgm"), 4, 2, 255, ACROSS);
        Path yaml = MapFixtures.yaml(dir.resolve("m.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]",
                "negate: 1");
        // negated, p = v / 255: free below 0.196, v 49 and down: only the 0
        assertThat(MapFixtures.picture(MapServerMap.read(yaml).grid())).isEqualTo("""
                ###.
                ####
                """);
        MapFixtures.yaml(yaml, "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]", "negate: true");
        assertThat(MapFixtures.picture(MapServerMap.read(yaml).grid())).isEqualTo("""
                ###.
                ####
                """);
    }

    @Test
    void withoutTheOptionalKeysMapServersDefaultsApply() throws IOException {
        MapFixtures.p5(dir.resolve("m.pgm"), 4, 2, 255, ACROSS);
        Path full = MapFixtures.yaml(dir.resolve("full.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [1, 1, 0]",
                "negate: 0", "occupied_thresh: 0.65", "free_thresh: 0.196", "mode: trinary");
        Path bare = MapFixtures.yaml(dir.resolve("bare.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [1, 1, 0]");
        assertThat(MapServerMap.read(bare).grid()).isEqualTo(MapServerMap.read(full).grid());
    }

    @Test
    void aPictureAloneIsReadAsAYamlGivingOnlyItsImageAndResolution() throws IOException {
        MapFixtures.p5(dir.resolve("m.pgm"), 4, 2, 255, ACROSS);
        MapFixtures.greyPng(dir.resolve("m.png"), 4, 2, ACROSS);
        Path bare = MapFixtures.yaml(dir.resolve("bare.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]");
        assertThat(MapFiles.read(dir.resolve("m.pgm"), 0.05).grid()).isEqualTo(MapServerMap.read(bare).grid());
        assertThat(MapFiles.read(dir.resolve("m.png"), 0.05).grid()).isEqualTo(MapServerMap.read(bare).grid());
        assertThat(MapFiles.takesCellSize(dir.resolve("m.png"))).isTrue();
        assertThat(MapFiles.takesCellSize(dir.resolve("bare.yaml"))).isFalse();
    }

    @Test
    void plainAndRawPgmAndPngGiveTheSameMapAndSixteenBitPixelsScale() throws IOException {
        MapFixtures.p5(dir.resolve("raw.pgm"), 4, 2, 255, ACROSS);
        MapFixtures.p2(dir.resolve("plain.pgm"), 4, 2, 255, ACROSS);
        MapFixtures.greyPng(dir.resolve("grey.png"), 4, 2, ACROSS);
        int[] wide = new int[ACROSS.length];
        for (int k = 0; k < wide.length; k++) {
            wide[k] = ACROSS[k] * 257; // 255 -> 65535
        }
        MapFixtures.p5(dir.resolve("wide.pgm"), 4, 2, 65535, wide);
        OccupancyGrid expected = null;
        for (String image : new String[] {"raw.pgm", "plain.pgm", "grey.png", "wide.pgm"}) {
            Path yaml = MapFixtures.yaml(dir.resolve(image + ".yaml"), "image: " + image, "resolution: 0.05",
                    "origin: [0, 0, 0]");
            OccupancyGrid g = MapServerMap.read(yaml).grid();
            if (expected == null) {
                expected = g;
            }
            assertThat(g).as(image).isEqualTo(expected);
        }
    }

    @Test
    void trinaryAveragesTheAlphaInAndScaleLeavesItOutAsMapServerDoes() throws IOException {
        // near-white, fully transparent: trinary's mean (250 * 3 + 0) / 4 = 187.5 is p 0.26, not free;
        // scale's mean over the colours alone is 250, p 0.02, free. An opaque black pixel is a wall in both.
        MapFixtures.argbPng(dir.resolve("a.png"), 2, 1, 0x00FAFAFA, 0xFF000000);
        Path trinary = MapFixtures.yaml(dir.resolve("t.yaml"), "image: a.png", "resolution: 0.05", "origin: [0, 0, 0]",
                "mode: trinary");
        Path scale = MapFixtures.yaml(dir.resolve("s.yaml"), "image: a.png", "resolution: 0.05", "origin: [0, 0, 0]",
                "mode: scale");
        assertThat(MapFixtures.picture(MapServerMap.read(trinary).grid())).isEqualTo("##\n");
        assertThat(MapFixtures.picture(MapServerMap.read(scale).grid())).isEqualTo(".#\n");
    }

    @Test
    void scaleModeKeepsOnlyFreeAsFloorAndTheValuesBetweenAsWalls() throws IOException {
        // 180: p 0.29, between the thresholds: map_server's scale mode gives it a cost (neither free nor occupied)
        MapFixtures.p5(dir.resolve("m.pgm"), 3, 1, 255, 250, 180, 20);
        Path yaml = MapFixtures.yaml(dir.resolve("m.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]",
                "mode: scale");
        assertThat(MapFixtures.picture(MapServerMap.read(yaml).grid())).isEqualTo(".##\n");
    }

    @Test
    void rawModeTakesTheValueItselfOnlyZeroFree() throws IOException {
        MapFixtures.p5(dir.resolve("m.pgm"), 4, 1, 255, 0, 1, 100, 255);
        Path raw = MapFixtures.yaml(dir.resolve("r.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]",
                "mode: raw");
        assertThat(MapFixtures.picture(MapServerMap.read(raw).grid())).isEqualTo(".###\n");
        Path negated = MapFixtures.yaml(dir.resolve("n.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]",
                "mode: raw", "negate: 1");
        assertThat(MapFixtures.picture(MapServerMap.read(negated).grid())).isEqualTo("###.\n");
    }

    @Test
    void theImageIsFoundBesideTheYamlNotInTheWorkingDirectory() throws IOException {
        Path sub = Files.createDirectories(dir.resolve("maps").resolve("floor2"));
        MapFixtures.p5(sub.resolve("m.pgm"), 4, 2, 255, ACROSS);
        Path yaml = MapFixtures.yaml(sub.resolve("m.yaml"), "image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]");
        assertThat(MapServerMap.read(yaml).grid().columns()).isEqualTo(4);
    }

    /** @return the problem reading a map made of these YAML lines (the image m.pgm, 4 x 2, beside it) */
    private MapException problem(String... yamlLines) throws IOException {
        if (!Files.exists(dir.resolve("m.pgm"))) {
            MapFixtures.p5(dir.resolve("m.pgm"), 4, 2, 255, ACROSS);
        }
        Path yaml = MapFixtures.yaml(dir.resolve("bad.yaml"), yamlLines);
        return catchThrowableOfType(() -> MapServerMap.read(yaml), MapException.class);
    }

    @Test
    void badYamlIsRefusedNamingTheFileAndTheProblem() throws IOException {
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0.3]").getMessage())
                .endsWith("bad.yaml: origin: the yaw must be 0 (a rotated map is not read), got 0.3");
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]", "occupied_thresh: 1.5").problem())
                .isEqualTo("occupied_thresh: must be from 0 to 1, got 1.5");
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]", "free_thresh: -0.1").problem())
                .isEqualTo("free_thresh: must be from 0 to 1, got -0.1");
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]", "free_thresh: 0.7").problem())
                .isEqualTo("free_thresh (0.7) must not be above occupied_thresh (0.65)");
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]", "mode: fancy").problem())
                .isEqualTo("mode: must be trinary, scale or raw, got fancy");
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]", "negate: 2").problem())
                .isEqualTo("negate: must be 0 or 1, got 2");
        assertThat(problem("image: m.pgm", "resolution: 0", "origin: [0, 0, 0]").problem())
                .isEqualTo("resolution: must be > 0 (metres a pixel), got 0.0");
        assertThat(problem("image: m.pgm", "origin: [0, 0, 0]").problem()).isEqualTo("resolution: missing required key");
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0]").problem())
                .isEqualTo("origin: expected [x, y, yaw], three numbers, got [0, 0]");
        assertThat(problem("image: m.pgm", "resolution: 0.05", "origin: [0, 0, 0]", "occupied: 0.6", "extra: 1").problem())
                .startsWith("unknown keys extra, occupied (a map_server YAML has free_thresh, image, mode, negate,");
        assertThat(problem("resolution: 0.05", "origin: [0, 0, 0]").problem()).isEqualTo("image: missing required key");
        assertThat(problem("- a list").problem()).startsWith("expected a map_server YAML");
        assertThat(problem("image: [unclosed").problem()).startsWith("not valid YAML");
    }

    @Test
    void aMissingYamlOrImageIsNamed() throws IOException {
        MapException noYaml = catchThrowableOfType(() -> MapServerMap.read(dir.resolve("none.yaml")), MapException.class);
        assertThat(noYaml.getMessage()).isEqualTo(dir.resolve("none.yaml") + ": no such file");
        MapException noImage = problem("image: gone.pgm", "resolution: 0.05", "origin: [0, 0, 0]");
        assertThat(noImage.file()).isEqualTo(dir.resolve("gone.pgm").toAbsolutePath());
        assertThat(noImage.problem()).isEqualTo("no such image file");
    }

    @Test
    void badPicturesAreRefusedNamingThePictureAndTheProblem() throws IOException {
        Files.write(dir.resolve("gif.pgm"), "GIF89a.....".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        assertThat(problem("image: gif.pgm", "resolution: 0.05", "origin: [0, 0, 0]").problem())
                .isEqualTo("wrong magic number: neither a PGM (P2, P5) nor a PNG image");
        Files.writeString(dir.resolve("ppm.pgm"), "P6\n1 1\n255\nabc");
        assertThat(problem("image: ppm.pgm", "resolution: 0.05", "origin: [0, 0, 0]").problem())
                .isEqualTo("a Netpbm P6 image: only PGM (P2, P5) and PNG are read");
        // a raw PGM a byte short of its header's 4 x 3, and one a byte long
        MapFixtures.p5(dir.resolve("short.pgm"), 4, 3, 255, new int[11]);
        MapException shortOne = problem("image: short.pgm", "resolution: 0.05", "origin: [0, 0, 0]");
        assertThat(shortOne.getMessage()).isEqualTo(dir.resolve("short.pgm").toAbsolutePath()
                + ": the header says 4 x 3 pixels (12 bytes) but the file holds 11 bytes of pixels");
        MapFixtures.p5(dir.resolve("long.pgm"), 4, 3, 255, new int[13]);
        assertThat(problem("image: long.pgm", "resolution: 0.05", "origin: [0, 0, 0]").problem())
                .isEqualTo("the header says 4 x 3 pixels (12 bytes) but the file holds 13 bytes of pixels");
        MapFixtures.p2(dir.resolve("plain.pgm"), 4, 3, 255, new int[11]);
        assertThat(problem("image: plain.pgm", "resolution: 0.05", "origin: [0, 0, 0]").problem())
                .isEqualTo("the header says 4 x 3 pixels but the file holds only 11");
        MapFixtures.p2(dir.resolve("over.pgm"), 2, 1, 100, 50, 101);
        assertThat(problem("image: over.pgm", "resolution: 0.05", "origin: [0, 0, 0]").problem())
                .isEqualTo("pixel 1 is 101, above the header's maxval 100");
        Files.writeString(dir.resolve("nowidth.pgm"), "P5\n# no size\n");
        assertThat(problem("image: nowidth.pgm", "resolution: 0.05", "origin: [0, 0, 0]").problem())
                .isEqualTo("the header has no width");
    }
}
