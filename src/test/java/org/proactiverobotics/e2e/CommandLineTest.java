package org.proactiverobotics.e2e;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import java.io.PrintWriter;
import java.io.StringWriter;
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
}
