package com.example.traffic;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.testkit.ScenarioKit;

/** KeepRight with ReachDestination, in a shared world and alone: something comes head-on. */
class KeepRightTest {

    private static final double FREE = 1.0;

    /** Something 0.7 m ahead comes 2 cm nearer every step while the robot stands still. */
    private static void somethingComes(ScenarioKit kit) {
        kit.mission().checkpoint(3.0, 0.0);
        for (int s = 0; s < 10; s++) {
            double d = 0.7 - 0.02 * s;
            kit.robot().gps(0.0, 0.0).headingDeg(0).scan(FREE, FREE, FREE, d, d, FREE, FREE, FREE);
            kit.step();
        }
    }

    @Test
    void inASharedWorldItVeersRightWhenSomethingComesHeadOn() {
        try (ScenarioKit kit = ScenarioKit.builder().sharedWorld().scenario(new KeepRightScenario())
                .builtIn("ReachDestination").start()) {
            somethingComes(kit);
            String[] w = kit.suggestion("KeepRight").split(" ");
            assertThat(Double.parseDouble(w[1])).as("left wheel faster: a right turn").isGreaterThan(Double.parseDouble(w[2]));
            assertThat(kit.decision().winner()).isEqualTo("KeepRight");
        }
    }

    @Test
    void aLoneRobotNeverVeers() {
        try (ScenarioKit kit = ScenarioKit.builder().scenario(new KeepRightScenario()).builtIn("ReachDestination").start()) {
            somethingComes(kit);
            assertThat(kit.suggestions("KeepRight")).containsOnlyNulls();
        }
    }
}
