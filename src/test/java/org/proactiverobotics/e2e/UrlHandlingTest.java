package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.ServerSocket;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A URL no driver takes is bad input for every command; a password in a URL is never printed. */
class UrlHandlingTest extends CommandLineTest {

    @TempDir
    Path tmp;

    @Test
    void aUrlNoDriverAcceptsIsBadInputForEveryCommand() {
        String url = "jdbc:postgresql://localhost/x";
        String[][] commands = {
                {"run", "--db", url, "--out", tmp.resolve("never").toString()},
                {"engine", "--db", url},
                {"robot", "--db", url, "--world", "reference-arena", "--out", tmp.resolve("never").toString()},
                {"strategy", "--db", url},
                {"db", "init", "--db", url},
                {"db", "users", "--db", url, "--engine-password", "e", "--robot-password", "r"}};
        for (String[] command : commands) {
            err.getBuffer().setLength(0);
            assertThat(run(command)).as(String.join(" ", command) + ": " + err).isEqualTo(2);
            assertThat(err.toString()).contains("driver").contains("jdbc:postgresql://localhost/x");
        }
        assertThat(tmp.resolve("never")).doesNotExist();
    }

    /** An H2 file URL as a user writes it, without MySQL mode: the settings the schema needs are added. */
    @Test
    void aPlainH2FileUrlKeepsTheMissionInThatFile() throws Exception {
        String url = "jdbc:h2:" + tmp.resolve("mission").toAbsolutePath();
        assertThat(run("run", "--db", url, "--world", "reference-arena", "--quiet", "--out", tmp.resolve("out").toString()))
                .as(err.toString()).isZero();
        try (java.sql.Connection c = java.sql.DriverManager.getConnection(url + ";MODE=MySQL;DATABASE_TO_LOWER=TRUE");
             java.sql.ResultSet rs = c.createStatement().executeQuery(
                     "SELECT (SELECT COUNT(*) FROM checkpoints), (SELECT COUNT(*) FROM gps_stored_values)")) {
            assertThat(rs.next()).isTrue();
            assertThat(rs.getInt(1)).as("the mission's checkpoints are in the file").isEqualTo(4);
            assertThat(rs.getInt(2)).as("and the robot's readings").isGreaterThan(1000);
        }
    }

    @Test
    void aPasswordInTheUrlIsNeverPrinted() throws Exception {
        int port;
        try (ServerSocket socket = new ServerSocket(0)) {
            port = socket.getLocalPort(); // closed again: nobody listens there
        }
        String url = "jdbc:mariadb://127.0.0.1:" + port + "/x?user=root&password=hunter2";
        String[][] commands = {
                {"run", "--db", url, "--wait-s", "0", "--out", tmp.resolve("out").toString()},
                {"strategy", "--db", url, "--wait-s", "0"},
                {"db", "init", "--db", url, "--wait-s", "0"},
                {"run", "--db", "jdbc:nosuch://h/x?password=hunter2"}};
        for (String[] command : commands) {
            out.getBuffer().setLength(0);
            err.getBuffer().setLength(0);
            assertThat(run(command)).as(String.join(" ", command)).isIn(2, 3);
            assertThat(out.toString() + err).as(String.join(" ", command)).doesNotContain("hunter2");
        }
    }
}
