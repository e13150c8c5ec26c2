package org.proactiverobotics.engine.robot;

import java.sql.Connection;
import java.sql.SQLException;

/**
 * A check run in every iteration's database transaction before the iteration's writes: when it
 * throws, nothing of the iteration commits. What keeps an engine that lost its robot to another
 * engine (a lease) from writing for it.
 */
@FunctionalInterface
public interface CommitGuard {
    /**
     * @param c         the iteration's connection, in its transaction
     * @param iteration the iteration about to commit
     * @throws SQLException to roll the iteration back
     */
    void check(Connection c, long iteration) throws SQLException;
}
