package org.proactiverobotics.app.foxglove;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Base64;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.sim2d.WorldSpec;

/** The pieces of run.mcap's messages: numbers as text, the scan's bearings, the engine's map as a grid. */
class FoxgloveMessagesTest {

    private static String text(JsonText j) {
        j.end();
        return new String(j.bytes(), 0, j.length(), StandardCharsets.UTF_8);
    }

    @Test
    void numbersAreWrittenWithTheirDecimalsTrailingZerosDropped() {
        JsonText j = new JsonText().begin().openArray().number(0, 3).number(1.5, 3).number(-2.0004, 3).number(0.05, 3)
                .number(-0.0004, 3).number(12.3456789, 6).number(1e-6, 6).number(-7.25, 2).integer(-3).closeArray();

        assertThat(text(j)).isEqualTo("[0,1.5,-2,0.05,0,12.345679,0.000001,-7.25,-3]");
    }

    @Test
    void stringsAreEscapedAndNonAsciiTextIsUtf8() {
        JsonText j = new JsonText().begin().open().name("m").string("a \"b\"\\\n\u0001 é→").close();

        String s = text(j);

        assertThat(s).isEqualTo("{\"m\":\"a \\\"b\\\"\\\\\\n\\u0001 é→\"}");
        assertThat(JsonParser.parseString(s).getAsJsonObject().get("m").getAsString()).isEqualTo("a \"b\"\\\n\u0001 é→");
    }

    @Test
    void theDefaultRaysKeepTheirExactAnglesOnOneDegreeBearings() {
        ScanLayout scan = ScanLayout.of(WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG);

        assertThat(scan.bearings).isEqualTo(181);
        assertThat(scan.startRad).isEqualTo(Math.toRadians(-90));
        assertThat(scan.endRad).isEqualTo(Math.toRadians(90));
        assertThat(scan.slot).containsExactly(0, 20, 40, 55, 70, 82, 98, 110, 125, 140, 160, 180);
    }

    @Test
    void raysNotInIncreasingOrderAreSpreadEvenly() {
        ScanLayout scan = ScanLayout.of(List.of(30.0, -30.0, 0.0));

        assertThat(scan.bearings).isEqualTo(3);
        assertThat(scan.slot).containsExactly(0, 1, 2);
    }

    @Test
    void theEngineMapBecomesAGridOverItsKnownCells() {
        MapGrid map = new MapGrid();
        assertThat(map.apply(new int[] {-2, 1, OccupancyMap.FREE, 1, 1, OccupancyMap.OCCUPIED, 0, 3, OccupancyMap.FREE}))
                .isTrue();
        assertThat(map.apply(new int[] {1, 1, OccupancyMap.OCCUPIED})).as("no change").isFalse();

        JsonText j = new JsonText();
        map.write(j, 2_500);
        JsonObject grid = JsonParser.parseString(text(j)).getAsJsonObject();

        assertThat(grid.getAsJsonObject("timestamp").get("sec").getAsInt()).isEqualTo(2);
        assertThat(grid.getAsJsonObject("timestamp").get("nsec").getAsInt()).isEqualTo(500_000_000);
        assertThat(grid.get("column_count").getAsInt()).isEqualTo(4);
        assertThat(grid.get("row_stride").getAsInt()).isEqualTo(4);
        JsonObject corner = grid.getAsJsonObject("pose").getAsJsonObject("position");
        assertThat(corner.get("x").getAsDouble()).isEqualTo(-0.1);
        assertThat(corner.get("y").getAsDouble()).isEqualTo(0.05);
        byte[] cells = Base64.getDecoder().decode(grid.get("data").getAsString());
        assertThat(cells).hasSize(4 * 3);
        byte[] expected = new byte[12];
        expected[0] = OccupancyMap.FREE; // (-2, 1): row 0, column 0
        expected[3] = OccupancyMap.OCCUPIED; // (1, 1): row 0, column 3
        expected[2 * 4 + 2] = OccupancyMap.FREE; // (0, 3): row 2, column 2
        assertThat(Arrays.equals(cells, expected)).as(Arrays.toString(cells)).isTrue();
    }
}
