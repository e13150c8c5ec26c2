package org.proactiverobotics.app.deploy;

import java.sql.SQLException;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.sql.DataSource;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where an engine process takes each robot's body from: the robot's {@code robot_body} row
 * ({@link RobotBody}), or the engine's {@code --max-speed-mps} / {@code --axle-width-m} (alone in
 * its world) when the
 * robot wrote none (a robot process of an older version) or the database has no such table yet (a
 * database made before it: one warning, then the options). Thread-safe.
 */
public final class EngineBodies implements RobotServer.Bodies {

    private static final Logger LOG = LoggerFactory.getLogger(EngineBodies.class);

    private final DataSource dataSource;
    private final RobotBody fallback;
    private final AtomicBoolean tableMissingSaid = new AtomicBoolean();

    /**
     * @param dataSource the shared database
     * @param fallback   the profile of a robot without a row (alone in its world)
     */
    public EngineBodies(DataSource dataSource, DriveProfile fallback) {
        this.dataSource = dataSource;
        this.fallback = new RobotBody(fallback, false);
    }

    @Override
    public RobotBody body(int robotId) throws SQLException {
        try {
            return RobotBody.read(dataSource, robotId).orElse(fallback);
        } catch (SQLException e) {
            if (!missingOrDenied(e)) {
                throw e; // the database is away: taken up again once it answers
            }
            if (tableMissingSaid.compareAndSet(false, true)) {
                LOG.warn("robot_body cannot be read ({}): every robot is driven with --max-speed-mps {} and --axle-width-m {}"
                        + " (run `db init` to add the table)", RobotServer.oneLine(e), fallback.drive().maxSpeedMps(), fallback.drive().axleWidthM());
            }
            return fallback;
        }
    }

    /** A table the database does not have, or may not be read: SQL state class 42 (syntax error or access rule violation). */
    static boolean missingOrDenied(SQLException e) {
        return e.getSQLState() != null && e.getSQLState().startsWith("42");
    }
}
