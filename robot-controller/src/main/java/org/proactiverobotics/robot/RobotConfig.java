package org.proactiverobotics.robot;

import org.proactiverobotics.robot.link.RetentionPolicy;

/**
 * How a robot controller behaves; build from {@link #defaults(int)} and the {@code with...}
 * methods.
 *
 * @param robotId           the robot's id in every table
 * @param watchdogTimeoutMs stop when no new command arrived for this long, simulated ms
 * @param retention         how much reading history to keep
 * @param backoffInitialMs  first wait after a database failure before trying again, wall-clock ms
 * @param backoffMaxMs      longest such wait, wall-clock ms
 * @param realTimeFactor    {@link RobotSuperclass#run()} pacing: 1 = real time, 2 = twice as fast,
 *                          0 = as fast as possible
 * @param seedMission       whether to seed the mission rows from the world at start
 */
public record RobotConfig(int robotId, long watchdogTimeoutMs, RetentionPolicy retention, long backoffInitialMs,
                          long backoffMaxMs, double realTimeFactor, boolean seedMission) {

    /** The default watchdog time-out, simulated ms. */
    public static final long DEFAULT_WATCHDOG_TIMEOUT_MS = 1000;

    /** Checks the values. */
    public RobotConfig {
        if (watchdogTimeoutMs <= 0) {
            throw new IllegalArgumentException("watchdogTimeoutMs must be > 0: " + watchdogTimeoutMs);
        }
        if (retention == null) {
            throw new IllegalArgumentException("retention must be given (RetentionPolicy.KEEP_ALL keeps everything)");
        }
        if (backoffInitialMs < 0 || backoffMaxMs < backoffInitialMs) {
            throw new IllegalArgumentException("need 0 <= backoffInitialMs <= backoffMaxMs");
        }
        if (!(realTimeFactor >= 0) || Double.isInfinite(realTimeFactor)) {
            throw new IllegalArgumentException("realTimeFactor must be finite and >= 0: " + realTimeFactor);
        }
    }

    /**
     * Watchdog 1000 ms (simulated), {@link RetentionPolicy#DEFAULT}, back-off 100 ms doubling to
     * 5 s, real-time pacing, mission seeded.
     *
     * @param robotId the robot's id
     * @return the defaults
     */
    public static RobotConfig defaults(int robotId) {
        return new RobotConfig(robotId, DEFAULT_WATCHDOG_TIMEOUT_MS, RetentionPolicy.DEFAULT, 100, 5_000, 1.0, true);
    }

    /** @return a copy with this watchdog time-out, simulated ms */
    public RobotConfig withWatchdogTimeoutMs(long ms) {
        return new RobotConfig(robotId, ms, retention, backoffInitialMs, backoffMaxMs, realTimeFactor, seedMission);
    }

    /** @return a copy with this retention */
    public RobotConfig withRetention(RetentionPolicy policy) {
        return new RobotConfig(robotId, watchdogTimeoutMs, policy, backoffInitialMs, backoffMaxMs, realTimeFactor, seedMission);
    }

    /** @return a copy with this back-off, wall-clock ms */
    public RobotConfig withBackoff(long initialMs, long maxMs) {
        return new RobotConfig(robotId, watchdogTimeoutMs, retention, initialMs, maxMs, realTimeFactor, seedMission);
    }

    /** @return a copy with this pacing of {@link RobotSuperclass#run()} (0 = unpaced) */
    public RobotConfig withRealTimeFactor(double factor) {
        return new RobotConfig(robotId, watchdogTimeoutMs, retention, backoffInitialMs, backoffMaxMs, factor, seedMission);
    }

    /** @return a copy that does (or does not) seed the mission rows at start */
    public RobotConfig withSeedMission(boolean seed) {
        return new RobotConfig(robotId, watchdogTimeoutMs, retention, backoffInitialMs, backoffMaxMs, realTimeFactor, seed);
    }
}
