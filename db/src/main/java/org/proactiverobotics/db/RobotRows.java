package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.util.List;

/**
 * Statements over one robot's rows whose only parameter is the robot's id: what a new run, a
 * fresh engine or a clean slate clears. They run on the caller's connection, in its transaction
 * when it has one open.
 */
public final class RobotRows {

    private RobotRows() {
    }

    /**
     * @param c          the connection
     * @param robotId    the robot
     * @param statements SQL statements, each with one '?': the robot's id
     * @throws SQLException when one fails (those after it do not run)
     */
    public static void run(Connection c, int robotId, List<String> statements) throws SQLException {
        for (String sql : statements) {
            try (PreparedStatement ps = c.prepareStatement(sql)) {
                ps.setInt(1, robotId);
                ps.executeUpdate();
            }
        }
    }

    /**
     * Deletes the robot's rows of each table.
     *
     * @param c       the connection
     * @param robotId the robot
     * @param tables  tables with a {@code robot_id} column
     * @throws SQLException when a delete fails
     */
    public static void delete(Connection c, int robotId, List<String> tables) throws SQLException {
        run(c, robotId, tables.stream().map(t -> "DELETE FROM " + t + " WHERE robot_id = ?").toList());
    }
}
