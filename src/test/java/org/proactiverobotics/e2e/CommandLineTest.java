package org.proactiverobotics.e2e;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.proactiverobotics.app.Main;
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
        return cl.execute(args);
    }
}
