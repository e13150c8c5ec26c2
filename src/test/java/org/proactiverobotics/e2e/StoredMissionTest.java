package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.app.Main;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import picocli.CommandLine;

/** A robot process never takes over another world's mission rows. */
class StoredMissionTest {

    @TempDir
    Path tmp;

    @Test
    void aRobotStartedWithAnotherWorldThanTheStoredMissionIsRefusedWithExitTwo() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            db.execute("INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m) VALUES (5, 0, 1.5, 1.5, 0.25)");
            db.execute("INSERT INTO recharge_station (robot_id, x_m, y_m, radius_m) VALUES (5, -3, 0, 0.35)");
            StringWriter err = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(new StringWriter(), true));
            cl.setErr(new PrintWriter(err, true));
            Path out = tmp.resolve("out");
            int code = cl.execute("robot", "--world", worldsDir() + "reference-arena.json",
                    "--db", db.jdbcUrl(), "--db-user", "sa", "--robot-id", "5", "--out", out.toString(), "--wait-s", "5");
            assertThat(code).as(err.toString()).isEqualTo(2);
            assertThat(err.toString()).contains("different mission for robot 5").contains("1 checkpoint stored");
            assertThat(db.count("checkpoints")).isEqualTo(1);
            assertThat(out.resolve("report.json")).doesNotExist();
        }
    }

    private static String worldsDir() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (p.resolve("worlds/reference-arena.json").toFile().isFile()) {
                return p.resolve("worlds") + "/";
            }
        }
        throw new IllegalStateException("no worlds/ directory");
    }
}
