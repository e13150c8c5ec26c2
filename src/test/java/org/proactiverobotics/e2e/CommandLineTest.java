package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import ch.qos.logback.classic.Logger;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.sql.DataSource;
import org.h2.jdbcx.JdbcDataSource;
import org.proactiverobotics.app.Main;
import org.slf4j.LoggerFactory;
import picocli.CommandLine;

/** Runs the real command line in this JVM and keeps what it printed, for the tests of its commands. */
abstract class CommandLineTest {

    /** What the commands printed on standard output. */
    protected final StringWriter out = new StringWriter();
    /** What the commands printed on standard error. */
    protected final StringWriter err = new StringWriter();

    /** @return the exit code of {@code proactive args...} */
    protected int run(String... args) {
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        // engine and robot raise the root log level to INFO for their status lines, as a process of their own
        // would for itself: here the rest of the tests would log at INFO
        Logger root = (Logger) LoggerFactory.getLogger(Logger.ROOT_LOGGER_NAME);
        Level level = root.getLevel();
        try {
            return cl.execute(args);
        } finally {
            root.setLevel(level);
        }
    }

    /**
     * Runs a mission with {@code run} into an H2 file database in the folder, the watch's way in.
     *
     * @param folder    where the database and the mission's output go
     * @param worldArgs the world: {@code "--world", NAME-OR-FILE}
     * @return a data source over that database, for LiveMission
     */
    protected DataSource missionInH2File(Path folder, String... worldArgs) {
        String url = "jdbc:h2:file:" + folder.resolve("db").resolve("p") + ";MODE=MySQL;DATABASE_TO_LOWER=TRUE";
        List<String> args = new ArrayList<>(List.of("run"));
        args.addAll(List.of(worldArgs));
        args.addAll(List.of("--db", url, "--db-user", "sa", "--db-password", "", "--quiet", "--out", folder.resolve("out").toString()));
        assertThat(run(args.toArray(String[]::new))).as(err.toString()).isZero();
        JdbcDataSource pool = new JdbcDataSource();
        pool.setURL(url);
        pool.setUser("sa");
        pool.setPassword("");
        return pool;
    }

    /** @return report.json less what depends on the machine's speed */
    protected static JsonObject deterministic(Path report) throws IOException {
        JsonObject o = JsonParser.parseString(Files.readString(report)).getAsJsonObject();
        o.remove("wallTimeS");
        o.remove("realTimeFactor");
        o.remove("timing");
        return o;
    }
}
