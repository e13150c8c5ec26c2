package org.proactiverobotics.app;

import com.zaxxer.hikari.HikariDataSource;
import java.io.IOException;
import java.io.PrintWriter;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.proactiverobotics.app.deploy.DatabaseProblem;
import org.proactiverobotics.app.deploy.DatabaseWait;
import org.proactiverobotics.app.deploy.DbOptions;
import org.proactiverobotics.app.deploy.ShutdownSignal;
import org.proactiverobotics.app.replay.LiveMission;
import org.proactiverobotics.app.replay.WatchServer;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.sim2d.WorldSpec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code watch}: serves replay.html live from the database of a running mission, reading only
 * (run it as {@code proactive_viewer}, which may only SELECT). Runs until SIGTERM or Ctrl-C.
 */
@Command(name = "watch",
        mixinStandardHelpOptions = true,
        description = {"Serves the replay view live at http://ADDRESS:PORT/ from the database of a running mission, reading only.",
                "Run it as the viewer's database user (proactive_viewer, SELECT only). Stops on SIGTERM or Ctrl-C.",
                "Exit codes: 0 stopped, 2 bad input (a port in use, an address that is not this machine's), 3 database not usable."})
public final class WatchCommand implements Callable<Integer> {

    /** How often the database is read, ms. */
    private static final long POLL_MS = 250;

    @Mixin
    private DbOptions db;

    @Option(names = "--robot-id", paramLabel = "N", defaultValue = "1", description = "The robot. Default: ${DEFAULT-VALUE}.")
    private int robotId;

    @Option(names = "--port", paramLabel = "P", defaultValue = "8080", description = "The TCP port. Default: ${DEFAULT-VALUE}.")
    private int port;

    @Option(names = "--bind", paramLabel = "ADDRESS", defaultValue = "127.0.0.1",
            description = "The address to listen on. Default: ${DEFAULT-VALUE} (this machine only).")
    private String bind;

    @Option(names = "--world", paramLabel = "FILE|NAME", completionCandidates = WorldArgument.BundledNames.class,
            description = "The mission's world, to draw its arena and obstacles (the database holds only the checkpoints"
                    + " and the station).")
    private String world;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        String problem = db.problem();
        if (problem == null && (port < 0 || port > 65535)) {
            problem = "--port must be 0 to 65535: " + port;
        }
        WorldSpec worldSpec = null;
        if (problem == null && world != null) {
            worldSpec = WorldArgument.load(world, err);
            if (worldSpec == null) {
                return Main.EXIT_BAD_INPUT;
            }
        }
        InetAddress address = null;
        if (problem == null) {
            try {
                address = InetAddress.getByName(bind);
            } catch (UnknownHostException e) {
                problem = "--bind " + bind + ": not an address of this machine (" + e.getMessage() + ")";
            }
        }
        if (problem != null) {
            err.println(problem);
            err.flush();
            return Main.EXIT_BAD_INPUT;
        }
        ShutdownSignal signal = ShutdownSignal.install();
        int code = Main.EXIT_INFRASTRUCTURE;
        try {
            code = serve(new InetSocketAddress(address, port), worldSpec, signal, out, err);
        } finally {
            signal.finished(code);
        }
        return code;
    }

    private int serve(InetSocketAddress address, WorldSpec worldSpec, ShutdownSignal signal, PrintWriter out, PrintWriter err) {
        try {
            if (!DatabaseWait.await(db, "engine_comments", signal::stopRequested)) {
                return 0;
            }
        } catch (DatabaseWait.Unreachable e) {
            err.println(e.getMessage());
            err.flush();
            return Main.EXIT_INFRASTRUCTURE;
        }
        try (HikariDataSource pool = Databases.pool(db.url(), db.user(), db.password())) {
            // a world of several robots: every robot followed, the page draws them all
            List<LiveMission> missions = new ArrayList<>();
            if (worldSpec != null && worldSpec.hasSeveralRobots()) {
                worldSpec.robots().forEach(r -> missions.add(new LiveMission(pool, r.id())));
            } else {
                missions.add(new LiveMission(pool, robotId));
            }
            LiveMission mission = missions.get(0);
            WatchServer server;
            try {
                server = missions.size() > 1 ? new WatchServer(address, worldSpec, missions)
                        : new WatchServer(address, mission, worldSpec, robotId);
            } catch (BindException e) {
                err.println("cannot listen on " + address.getAddress().getHostAddress() + " port " + address.getPort()
                        + ": " + e.getMessage() + " (the port is in use, or the address is not this machine's; choose"
                        + " another with --port or --bind)");
                err.flush();
                return Main.EXIT_BAD_INPUT;
            } catch (IOException e) {
                err.println("cannot listen on " + address + ": " + e.getMessage());
                err.flush();
                return Main.EXIT_INFRASTRUCTURE;
            }
            try (server) {
                String who = missions.size() > 1 ? "robots " + worldSpec.robots().stream().map(r -> String.valueOf(r.id()))
                        .collect(Collectors.joining(", ")) : "robot " + robotId;
                out.printf(Locale.ROOT, "Watching %s: http://%s:%d/ (Ctrl-C stops)%n", who,
                        server.address().getAddress().getHostAddress(), server.address().getPort());
                out.flush();
                boolean failing = false;
                while (!signal.stopRequested()) {
                    try {
                        for (LiveMission m : missions) {
                            m.poll();
                        }
                        if (failing) {
                            log().info("watch: the database answers again");
                            failing = false;
                        }
                        server.status(missions.stream().allMatch(m -> m.data().size() == 0) ? "waiting for the mission" : "");
                    } catch (java.sql.SQLException | RuntimeException e) {
                        String why = DatabaseProblem.of(e, db.url(), "watch").message();
                        if (!failing) {
                            log().warn("watch: reading the database failed, retrying: {}", why);
                            failing = true;
                        }
                        server.status("database: " + why + " (retrying)");
                    }
                    Thread.sleep(POLL_MS);
                }
            }
            return 0;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 0;
        }
    }

    /**
     * The logger, looked up when first used: a static one would start logback (about 0.2 s) in every command,
     * since picocli makes an instance of each subcommand to build the command line.
     */
    private static Logger log() {
        return LoggerFactory.getLogger(WatchCommand.class);
    }
}
