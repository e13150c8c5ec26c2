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
