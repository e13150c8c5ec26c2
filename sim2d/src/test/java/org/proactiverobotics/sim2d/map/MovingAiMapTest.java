package org.proactiverobotics.sim2d.map;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Moving AI grid maps: the header, every terrain letter, the first row on top, the cell size. */
class MovingAiMapTest {

    @TempDir
    Path dir;

    @Test
    void everyTerrainIsFreeOrBlockedAndTheFirstRowIsTheTop() throws IOException {
        Path file = Files.writeString(dir.resolve("m.map"), "type octile\nheight 3\nwidth 4\nmap\n.@GS\nTOW.\n....\n");
        MapReading map = MovingAiMap.read(file, 0.5);
        OccupancyGrid g = map.grid();
        assertThat(MapFixtures.picture(g)).isEqualTo("""
                .#..
                ###.
                ....
                """);
        assertThat(g.cellM()).isEqualTo(0.5);
        assertThat(g.originX()).isZero();
        assertThat(g.originY()).isZero();
        assertThat(g.widthM()).isEqualTo(2.0);
        assertThat(g.heightM()).isEqualTo(1.5);
        assertThat(MapFiles.read(file, 0.25).grid().widthM()).isEqualTo(1.0); // dispatched by the name, cell size given
    }

    @Test
    void windowsLineEndsAndATrailingBlankLineAreRead() throws IOException {
        Path file = Files.writeString(dir.resolve("m.map"), "type octile\r\nheight 1\r\nwidth 2\r\nmap\r\n.@\r\n\r\n");
        assertThat(MapFixtures.picture(MovingAiMap.read(file, 1.0).grid())).isEqualTo(".#\n");
    }

    private String problem(String text) throws IOException {
        Path file = Files.writeString(dir.resolve("bad.map"), text);
        MapException e = catchThrowableOfType(() -> MovingAiMap.read(file, 0.5), MapException.class);
        assertThat(e.file()).isEqualTo(file);
        return e.problem();
    }

    @Test
    void badMapsAreRefusedNamingTheProblem() throws IOException {
        assertThat(problem("type octile\nheight 2\nwidth 2\nmap\n..\n.X\n"))
                .isEqualTo("row 2, column 2: 'X' is no terrain of a Moving AI map (. G S free, @ O T W blocked)");
        assertThat(problem("type octile\nheight 2\nwidth 3\nmap\n...\n..\n"))
                .isEqualTo("row 2 has 2 cells, the header says width 3");
        assertThat(problem("type octile\nheight 3\nwidth 2\nmap\n..\n..\n"))
                .isEqualTo("the header says height 3 but the map has 2 rows");
        assertThat(problem("type tile\nheight 1\nwidth 1\nmap\n.\n")).isEqualTo("type tile is not read: only octile maps");
        assertThat(problem("type octile\nwidth 1\nheight 1\nmap\n.\n")).isEqualTo("expected \"height N\", got \"width 1\"");
        assertThat(problem("type octile\nheight 0\nwidth 1\nmap\n")).isEqualTo("height must be a whole number from 1, got 0");
        assertThat(problem("P5\n")).startsWith("not a Moving AI map");
    }
}
