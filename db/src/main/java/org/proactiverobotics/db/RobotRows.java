package org.proactiverobotics.db;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.List;

/**
 * Statements over one robot's rows: what a new run, a fresh engine or a clean slate clears, and
 * what retention prunes. They run on the caller's connection, in its transaction when it has one
 * open.
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

    /**
     * Deletes the robot's rows older than its keep-th newest, newest by {@code order} then id (the
     * history's retention). Never by id alone for a row's age: ids from different Galera nodes
     * interleave; two rows of one {@code order} value are cut between them by id.
     *
     * @param c             the connection
     * @param robotId       the robot
     * @param table         a table with {@code robot_id}, {@code id} and the order column
     * @param order         the column rows age by: {@code sim_time_ms}, {@code iteration}, or {@code id}
     * @param filter        more conditions, starting with " AND ", or ""
     * @param keep          how many of the newest rows stay
     * @param queryTimeoutS a time-out for each statement, seconds, or 0 for none
     * @return the rows deleted
     * @throws SQLException when a statement fails
     */
    public static int pruneOlderThanNewest(Connection c, int robotId, String table, String order, String filter, int keep,
                                           int queryTimeoutS) throws SQLException {
        boolean byId = order.equals("id");
        long cutoff;
        long cutoffId;
        try (PreparedStatement ps = c.prepareStatement("SELECT " + order + ", id FROM " + table + " WHERE robot_id = ?" + filter
                + " ORDER BY robot_id DESC, " + (byId ? "" : order + " DESC, ") + "id DESC LIMIT 1 OFFSET " + keep)) {
            ps.setQueryTimeout(queryTimeoutS);
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                if (!rs.next()) {
                    return 0;
                }
                cutoff = rs.getLong(1);
                cutoffId = rs.getLong(2);
            }
        }
        String older = byId ? "id <= ?" : "(" + order + " < ? OR " + order + " = ? AND id <= ?)";
        try (PreparedStatement ps = c.prepareStatement("DELETE FROM " + table + " WHERE robot_id = ? AND " + older + filter)) {
            ps.setQueryTimeout(queryTimeoutS);
            ps.setInt(1, robotId);
            ps.setLong(2, cutoff);
            if (!byId) {
                ps.setLong(3, cutoff);
                ps.setLong(4, cutoffId);
            }
            return ps.executeUpdate();
        }
    }
}
