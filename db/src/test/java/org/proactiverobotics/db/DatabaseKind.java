package org.proactiverobotics.db;

/** The databases every database test runs against. */
public enum DatabaseKind {
    /** Embedded H2 in MySQL mode: always available. */
    H2,
    /** A real MariaDB (or MySQL 8) server, given by the PROACTIVE_TEST_MARIADB_URL environment variable. */
    MARIADB
}
