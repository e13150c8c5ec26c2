package org.proactiverobotics.engine.scenario.battery;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The cost of travel, learnt from GPS and battery readings, noisy ones included. */
class DrainEstimateTest {

    /** Drives 4 m straight in 1.6 cm steps at 1 % per metre, the GPS off by {@code sigmaM} each step. */
    private static DrainEstimate drive(double sigmaM) {
        SplittableRandom random = new SplittableRandom(7);
        DrainEstimate drain = new DrainEstimate();
        double level = 100.0;
        for (int step = 0; step <= 250; step++) {
            double x = step * 0.016;
            drain.position(x + sigmaM * gaussian(random), sigmaM * gaussian(random));
            if (step % 10 == 0) {
                drain.battery(step * 32L, level - x * 1.0, false);
            }
        }
        return drain;
    }

    private static double gaussian(SplittableRandom random) {
        return Math.sqrt(-2 * Math.log(1 - random.nextDouble())) * Math.cos(2 * Math.PI * random.nextDouble());
    }

    @Test
    void exactReadingsGiveTheCostPerMetre() {
        assertThat(drive(0.0).pctPerMetre()).isCloseTo(1.0, offset(0.1));
    }

    @Test
    void gpsNoiseDoesNotMakeTravelLookCheaper() {
        // summed step by step, 5 cm of noise on 1.6 cm steps counted several times the distance: 0.2 %/m
        double perMetre = drive(0.05).pctPerMetre();
        assertThat(perMetre).as("at least the true cost, within 25 %").isBetween(0.95, 1.25);
    }
}
