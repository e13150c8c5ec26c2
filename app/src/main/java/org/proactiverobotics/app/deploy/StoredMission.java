package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import javax.sql.DataSource;
import org.proactiverobotics.app.Plural;
import org.proactiverobotics.robot.link.MissionSpec;

/**
 * Compares the mission rows a database already holds for a robot with the world a robot process
 * was started with. Seeding never overwrites them (a restarted robot keeps its mission), so a
 * robot started with another world would otherwise chase the old world's checkpoints.
 */
public final class StoredMission {

    /** Coordinates closer than this are the same, metres. */
    private static final double SAME_M = 1e-6;

    private StoredMission() {
    }

    /** Why a robot cannot start: the stored mission differs from its world. */
    public static final class Mismatch extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Mismatch(String message) {
            super(message);
        }
    }

    /**
     * @param dataSource the shared database
     * @param robotId    the robot
     * @param mission    the mission of the robot's world
     * @throws Mismatch  naming the difference, when the stored checkpoints or station differ
     * @throws SQLException when the rows cannot be read
     */
    public static void check(DataSource dataSource, int robotId, MissionSpec mission) throws SQLException {
        List<double[]> stored = new ArrayList<>();
        Optional<double[]> station = Optional.empty();
        try (Connection c = dataSource.getConnection()) {
            try (PreparedStatement ps = c.prepareStatement(
                    "SELECT x_m, y_m FROM checkpoints WHERE robot_id = ? ORDER BY seq")) {
                ps.setInt(1, robotId);
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        stored.add(new double[] {rs.getDouble(1), rs.getDouble(2)});
                    }
                }
            }
            try (PreparedStatement ps = c.prepareStatement("SELECT x_m, y_m FROM recharge_station WHERE robot_id = ?")) {
                ps.setInt(1, robotId);
                try (ResultSet rs = ps.executeQuery()) {
                    if (rs.next()) {
                        station = Optional.of(new double[] {rs.getDouble(1), rs.getDouble(2)});
                    }
                }
            }
        }
        if (stored.isEmpty() && station.isEmpty()) {
            return; // nothing stored yet: the robot seeds its own mission
        }
        boolean same = stored.size() == mission.checkpoints().size();
        for (int i = 0; same && i < stored.size(); i++) {
            MissionSpec.Checkpoint cp = mission.checkpoints().get(i);
            same = near(stored.get(i), cp.xM(), cp.yM());
        }
        same = same && station.map(s -> near(s, mission.station().xM(), mission.station().yM())).orElse(true);
        if (!same) {
            throw new Mismatch(String.format(Locale.ROOT, "the database already holds a different mission for robot %d"
                    + " (%s stored, the world has %d): start this world with another --robot-id, or on an"
                    + " empty database", robotId, Plural.of(stored.size(), "checkpoint"), mission.checkpoints().size()));
        }
    }

    private static boolean near(double[] stored, double x, double y) {
        return Math.abs(stored[0] - x) < SAME_M && Math.abs(stored[1] - y) < SAME_M;
    }
}
