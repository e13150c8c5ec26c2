package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import org.junit.jupiter.api.Test;
import org.slf4j.LoggerFactory;

/** A skipped MariaDB test says why on the console, once per JVM, not only in the surefire XML. */
class SkipNoticeTest {

    @Test
    void theFirstSkipWarnsOnceNamingTheVariable() {
        Logger log = (Logger) LoggerFactory.getLogger(SkipNoticeTest.class);
        ListAppender<ILoggingEvent> seen = new ListAppender<>();
        seen.start();
        log.addAppender(seen);
        log.setAdditive(false); // seen here, not on the console
        try {
            TestDatabases.SkipNotice notice = new TestDatabases.SkipNotice(log);
            notice.skipped();
            notice.skipped();
            notice.skipped();
        } finally {
            log.detachAppender(seen);
            log.setAdditive(true);
        }
        assertThat(seen.list).singleElement().satisfies(e -> {
            assertThat(e.getLevel()).isEqualTo(Level.WARN);
            assertThat(e.getFormattedMessage()).contains("MariaDB tests skipped").contains(TestDatabases.MARIADB_URL_VARIABLE);
        });
    }
}
