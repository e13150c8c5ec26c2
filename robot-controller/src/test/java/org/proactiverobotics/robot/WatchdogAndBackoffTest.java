package org.proactiverobotics.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.Backoff;

class WatchdogAndBackoffTest {

    @Test
    void watchdogIsNotArmedBeforeTheFirstCommandAndExpiresAfterItsTimeout() {
        Watchdog w = new Watchdog(100);
        assertThat(w.expired(1_000_000)).isFalse();
        w.feed(1000);
        assertThat(w.expired(1100)).isFalse();
        assertThat(w.expired(1101)).isTrue();
        w.feed(1101);
        assertThat(w.expired(1150)).isFalse();
    }

    @Test
    void backoffDoublesUpToItsCeilingAndResetsOnSuccess() {
        AtomicLong now = new AtomicLong();
        Backoff b = new Backoff(10, 35, now::get);
        assertThat(b.ready()).isTrue();
        b.failed();
        assertThat(b.delayMs()).isEqualTo(10);
        assertThat(b.ready()).isFalse();
        now.addAndGet(10_000_000L);
        assertThat(b.ready()).isTrue();
        b.failed();
        assertThat(b.delayMs()).isEqualTo(20);
        b.failed();
        assertThat(b.delayMs()).isEqualTo(35);
        b.succeeded();
        assertThat(b.failing()).isFalse();
        assertThat(b.ready()).isTrue();
        b.failed();
        assertThat(b.delayMs()).isEqualTo(10);
    }
}
