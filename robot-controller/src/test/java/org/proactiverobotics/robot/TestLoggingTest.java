package org.proactiverobotics.robot;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.slf4j.LoggerFactory;

/** The build log stays readable: this module's tests open many pools, and HikariCP describes each at DEBUG. */
class TestLoggingTest {

    @Test
    void hikariLogsOnlyWarningsInTheTests() {
        assertThat(LoggerFactory.getLogger("com.zaxxer.hikari.HikariConfig").isInfoEnabled()).isFalse();
        assertThat(LoggerFactory.getLogger("com.zaxxer.hikari.pool.HikariPool").isWarnEnabled()).isTrue();
    }
}
