package org.proactiverobotics.app.deploy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import javax.sql.DataSource;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.StateStoreException;
import org.proactiverobotics.engine.robot.RobotEngine;

/** A robot's lease is one engine's at a time, and an engine that lost it commits nothing more for the robot. */
class EngineLeaseTest {

    private static final int ROBOT = 7;
    /** Long enough that a loaded machine cannot let it expire between two statements by accident. */
    private static final int LEASE_MS = 4000;

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void anEngineThatLostTheLeaseCommitsNothingAndTheNewOwnerKeepsIt(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            DataSource ds = db.dataSource();
            Schema.apply(ds);
            EngineLease a = new EngineLease(ds, ROBOT, "engine-a", LEASE_MS);
            EngineLease b = new EngineLease(ds, ROBOT, "engine-b", LEASE_MS);
            assertThat(a.tryTake()).isTrue();
            assertThat(b.tryTake()).as("held by A and not expired").isFalse();

            RobotEngine engineA = RobotEngine.builder().robotId(ROBOT).database(ds).guard(a::confirm).build();
            engineA.startFresh();
            engineA.iterate();
            engineA.iterate();
            assertThat(value(ds, "SELECT iteration FROM engine_lease WHERE robot_id = " + ROBOT)).isEqualTo(2);
            long saved = value(ds, "SELECT iteration FROM engine_state WHERE robot_id = " + ROBOT);
            assertThat(saved).isEqualTo(2);

            Thread.sleep(LEASE_MS + 200L); // A stalls past its lease (a long GC, a frozen VM): B takes the robot over
            assertThat(b.tryTake()).isTrue();
            assertThat(b.epoch()).isEqualTo(2);

            assertThatThrownBy(engineA::iterate).isInstanceOf(StateStoreException.class)
                    .hasCauseInstanceOf(EngineLease.LostException.class).hasMessageContaining("lost the lease");
            assertThat(a.held()).isFalse();
            assertThat(value(ds, "SELECT iteration FROM engine_state WHERE robot_id = " + ROBOT))
                    .as("A's iteration after losing the lease is not saved").isEqualTo(saved);
            assertThat(value(ds, "SELECT iteration FROM engine_lease WHERE robot_id = " + ROBOT)).isEqualTo(2);
            assertThat(value(ds, "SELECT COUNT(*) FROM engine_comments WHERE robot_id = " + ROBOT + " AND iteration > " + saved))
                    .isZero();
            assertThat(a.tryTake()).as("B renews it: A cannot take it back").isFalse();
            assertThat(b.renew()).isTrue();

            // B restarted (same name, new process): it takes its own lease back at once, and its earlier life is out
            EngineLease bAgain = new EngineLease(ds, ROBOT, "engine-b", LEASE_MS);
            assertThat(bAgain.tryTake()).isTrue();
            assertThat(bAgain.epoch()).isEqualTo(3);
            assertThat(b.renew()).isFalse();

            // a clean stop releases it: another engine takes it without waiting
            bAgain.release();
            assertThat(a.tryTake()).isTrue();
            assertThat(value(ds, "SELECT epoch FROM engine_lease WHERE robot_id = " + ROBOT)).isEqualTo(4);
        }
    }

    private static long value(DataSource ds, String sql) throws SQLException {
        try (Connection c = ds.getConnection(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }
}
