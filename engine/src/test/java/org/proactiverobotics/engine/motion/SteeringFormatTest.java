package org.proactiverobotics.engine.motion;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The engine's fast number formatting writes exactly what String.format did, so commands and traces stay the same bytes. */
class SteeringFormatTest {

    private static String fast(double v) {
        return Steering.appendFixed4(new StringBuilder(), v).toString();
    }

    @Test
    void fourDecimalsAsStringFormatWritesThemForEdgesAndManySeededValues() {
        double[] edges = {0.0, -0.0, 0.00005, -0.00005, 0.00004999, 0.5, -0.5, 1e-9, -1e-9, 0.15, 0.25, 2.00005,
                0.30000000000000004, 0.49999999999999994, 12345.67895, -0.00015, Double.MIN_VALUE, -Double.MIN_VALUE};
        for (double v : edges) {
            assertThat(fast(v)).as("%s", v).isEqualTo(String.format(Locale.ROOT, "%.4f", v));
        }
        SplittableRandom random = new SplittableRandom(42);
        for (int i = 0; i < 200_000; i++) {
            double v = switch (i % 4) {
                case 0 -> random.nextDouble(-1, 1);
                case 1 -> Math.round(random.nextDouble(-1, 1) * 100_000) / 100_000.0; // ties at the fifth decimal
                case 2 -> (random.nextInt(-20_000, 20_000) + 0.5) / 10_000.0;
                default -> random.nextDouble(-1e-4, 1e-4);
            };
            assertThat(fast(v)).as("%s", v).isEqualTo(String.format(Locale.ROOT, "%.4f", v));
        }
    }

    @Test
    void aDriveCommandReadsAsBefore() {
        assertThat(Steering.drive(0.3, 0.0, DriveProfile.DEFAULT)).isEqualTo("DRIVE 0.3000 0.3000");
        assertThat(Steering.drive(0.0, 1.0, DriveProfile.DEFAULT)).isEqualTo("DRIVE -0.1200 0.1200");
        assertThat(Steering.drive(Double.NaN, 0, DriveProfile.DEFAULT)).isEqualTo(Steering.STOP);
    }
}
