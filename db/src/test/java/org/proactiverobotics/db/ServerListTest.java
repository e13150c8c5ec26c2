package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * A list of servers for the driver to fail over between (a Galera cluster's nodes): the pool's
 * connections wait for the cluster's newest writes before a read, and the handshake does not rely
 * on locks a Galera node keeps to itself. On the test MariaDB, named twice in the list.
 */
class ServerListTest {

    @Test
    void aServerListsConnectionsReadTheClustersNewestAndAPlainUrlsDoNot() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB)) {
            Matcher m = Pattern.compile("jdbc:mariadb://([^/?]+)(/.*)").matcher(db.jdbcUrl());
            assertThat(m.matches()).as(db.jdbcUrl()).isTrue();
            String list = "jdbc:mariadb:sequential://" + m.group(1) + "," + m.group(1) + m.group(2);
            assertThat(Databases.isServerList(list)).isTrue();
            assertThat(Databases.isServerList(db.jdbcUrl())).isFalse();
            try (HikariDataSource pool = Databases.pool(list, db.user(), db.password())) {
                assertThat(syncWait(pool)).isOne();
            }
            try (HikariDataSource pool = Databases.pool(db.jdbcUrl(), db.user(), db.password())) {
                assertThat(syncWait(pool)).isZero();
            }
            String more = list + (list.contains("?") ? "&" : "?") + "sessionVariables=max_join_size=1000000";
            try (HikariDataSource pool = Databases.pool(more, db.user(), db.password()); Connection c = pool.getConnection();
                 Statement st = c.createStatement();
                 ResultSet rs = st.executeQuery("SELECT @@session.wsrep_sync_wait, @@session.max_join_size")) {
                rs.next();
                assertThat(rs.getInt(1)).as("added to the URL's own session variables").isOne();
                assertThat(rs.getLong(2)).isEqualTo(1_000_000L);
            }
            String own = list + (list.contains("?") ? "&" : "?") + "sessionVariables=wsrep_sync_wait=0";
            try (HikariDataSource pool = Databases.pool(own, db.user(), db.password())) {
                assertThat(syncWait(pool)).as("a setting in the URL wins").isZero();
            }
        }
    }

    @Test
    void onAServerWithoutGaleraTheHandshakeKeepsItsLocks() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB);
             HikariDataSource pool = Databases.multiStatementPool(db.jdbcUrl(), db.user(), db.password());
             HandshakeLocks locks = new HandshakeLocks(pool, 1)) {
            assertThat(locks.usable()).as("wsrep_on is 0 on the test server").isTrue();
        }
    }

    private static int syncWait(HikariDataSource pool) throws Exception {
        try (Connection c = pool.getConnection(); Statement st = c.createStatement();
             ResultSet rs = st.executeQuery("SELECT @@session.wsrep_sync_wait")) {
            rs.next();
            return rs.getInt(1);
        }
    }
}
