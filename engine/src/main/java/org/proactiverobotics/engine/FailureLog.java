package org.proactiverobotics.engine;

import java.util.HashMap;
import java.util.Map;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Logs rule failures without flooding: the first failure of a rule part with a given error is
 * a WARN with its stack trace, repeats are DEBUG, and every {@value #SUMMARY_EVERY}th repeat a
 * one-line WARN says how often it has failed. Every failure is still recorded and shown to
 * listeners and rules; only the log is thinned.
 */
final class FailureLog {

    static final long SUMMARY_EVERY = 1000;
    private static final Logger LOG = LoggerFactory.getLogger(ProactiveEngine.class);

    private final Map<String, Long> seen = new HashMap<>();

    void failed(RuleFailure failure, Throwable cause) {
        String key = failure.scenario() + '/' + failure.rule() + '/' + failure.part() + '/' + cause.getClass().getName();
        long count = seen.merge(key, 1L, Long::sum);
        if (count == 1) {
            LOG.warn("{}", failure, cause);
        } else if (count % SUMMARY_EVERY == 0) {
            LOG.warn("{}/{} has failed in {} {} times (latest: {})", failure.scenario(), failure.rule(), failure.part(),
                    count, failure.message());
        } else {
            LOG.debug("{}", failure, cause);
        }
    }
}
