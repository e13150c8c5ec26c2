package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code run --link}: the same mission over the direct in-process link. */
class RunLinkOptionTest extends CommandLineTest {

    @TempDir
    Path tmp;

    @Test
    void linkDirectRunsTheSameMissionWithoutADatabase() throws Exception {
        Path outDir = tmp.resolve("direct");
        assertThat(run("run", "--link", "direct", "--out", outDir.toString(), "--quiet")).as(err.toString()).isZero();
        JsonObject report = JsonParser.parseString(Files.readString(outDir.resolve("report.json"))).getAsJsonObject();
        assertThat(report.get("database").getAsString()).isEqualTo("direct");
        assertThat(report.get("controlSteps").getAsLong()).isEqualTo(Missions.onH2("reference-arena").report().controlSteps());
        assertThat(out.toString()).contains("direct");
    }

    @Test
    void anUnknownLinkOrADatabaseWithTheDirectLinkIsBadInput() {
        assertThat(run("run", "--link", "carrier-pigeon", "--out", tmp.resolve("a").toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--link must be jdbc or direct");
        assertThat(run("run", "--link", "direct", "--db", "jdbc:h2:mem:x", "--out", tmp.resolve("b").toString())).isEqualTo(2);
        assertThat(err.toString()).contains("drop --db");
        assertThat(tmp.resolve("a")).doesNotExist();
        assertThat(tmp.resolve("b")).doesNotExist();
    }
}
