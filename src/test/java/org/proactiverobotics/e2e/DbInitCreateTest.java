package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.proactiverobotics.db.TestDatabases;

/**
 * {@code db init --create} (issue 16): without it a missing database fails at once with exit 3
 * saying how to create it; with it the database is created (when the user may) and the schema
 * applied, and repeating it is harmless.
 */
class DbInitCreateTest extends CommandLineTest {

    private static final Pattern SERVER = Pattern.compile("(jdbc:(?:mariadb|mysql)://[^/?]+)/([^?]*)(\\?.*)?");

    @TempDir
    Path tmp;

    @Test
    void createsAMissingMariaDbDatabaseOnlyWhenAsked() throws Exception {
        String base = TestDatabases.mariaDbUrl();
        Assumptions.assumeTrue(base != null, "needs a MariaDB server: set " + TestDatabases.MARIADB_URL_VARIABLE + " to run it");
        Matcher m = SERVER.matcher(base);
        assertThat(m.matches()).as(base).isTrue();
        String name = "proactive_create_" + UUID.randomUUID().toString().substring(0, 8);
        String url = m.group(1) + "/" + name + (m.group(3) == null ? "" : m.group(3));
        try {
            long start = System.nanoTime();
            assertThat(run("db", "init", "--db", url, "--wait-s", "30")).isEqualTo(3);
            assertThat(System.nanoTime() - start).as("an unknown database is not waited for").isLessThan(TimeUnit.SECONDS.toNanos(8));
            assertThat(err.toString()).contains("Unknown database '" + name + "'").contains("db init --create");
            assertThat(tables(base, name)).isZero();

            assertThat(run("db", "init", "--create", "--db", url, "--wait-s", "1")).as(err.toString()).isZero();
            assertThat(out.toString()).contains("database " + name + " created").contains("schema.sql applied");
            int tables = tables(base, name);
            assertThat(tables).isGreaterThan(8);

            assertThat(run("db", "init", "--create", "--db", url, "--wait-s", "1")).as(err.toString()).isZero();
            assertThat(tables(base, name)).isEqualTo(tables);
        } finally {
            try (Connection c = DriverManager.getConnection(base); Statement s = c.createStatement()) {
                s.execute("DROP DATABASE IF EXISTS `" + name + "`");
            }
        }
    }

    @Test
    void anH2FileDatabaseIsCreatedWithOrWithoutTheFlag() {
        String url = "jdbc:h2:file:" + tmp.resolve("proactive") + ";MODE=MySQL;DATABASE_TO_LOWER=TRUE";
        assertThat(run("db", "init", "--create", "--db", url, "--db-user", "sa", "--wait-s", "1")).as(err.toString()).isZero();
        assertThat(out.toString()).contains("schema.sql applied").doesNotContain("created");
        assertThat(tmp.resolve("proactive.mv.db")).isRegularFile();
    }

    @Test
    void aDatabaseNameThatWouldNeedQuotingIsBadInput() {
        assertThat(run("db", "init", "--create", "--db", "jdbc:mariadb://127.0.0.1:1/bad`name", "--wait-s", "0")).isEqualTo(2);
        assertThat(err.toString()).contains("--create needs a database name");
    }

    /** @return how many tables the database holds (0 when it does not exist) */
    private static int tables(String base, String database) throws Exception {
        try (Connection c = DriverManager.getConnection(base); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT COUNT(*) FROM information_schema.tables WHERE table_schema = '"
                     + database + "'")) {
            rs.next();
            return rs.getInt(1);
        }
    }
}
