package org.proactiverobotics.app.mission;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.proactiverobotics.sim2d.SensorNoise;

/**
 * The sensor noise levels of {@code --noise} on {@code run}, {@code robot} and {@code sweep}: seeded
 * Gaussian noise on GPS, inertial unit and distance sensors, drawn from the world's {@code seed}.
 * {@link #NONE} is the run of the world file alone.
 */
public enum NoiseLevel {
    /** Perfect sensors. */
    NONE(SensorNoise.NONE),
    /** 1 cm on each GPS coordinate, 0.5° on the yaw, 1 cm on each distance ray. */
    SMALL(SensorNoise.SMALL),
    /** 5 cm on each GPS coordinate, 2° on the yaw, 3 cm on each distance ray: a cheap indoor robot. */
    REALISTIC(new SensorNoise(0.05, Math.toRadians(2.0), 0.03));

    private final SensorNoise noise;

    NoiseLevel(SensorNoise noise) {
        this.noise = noise;
    }

    /** @return the standard deviations the simulator draws with */
    public SensorNoise sensorNoise() {
        return noise;
    }

    /** @return the name on the command line and in results.csv: none, small, realistic */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @return every level's label, in order */
    public static List<String> labels() {
        return Arrays.stream(values()).map(NoiseLevel::label).toList();
    }

    /**
     * @param label a level's label, in any case ({@code Realistic} is {@code realistic})
     * @return the level
     * @throws IllegalArgumentException naming the label and the levels there are
     */
    public static NoiseLevel of(String label) {
        for (NoiseLevel level : values()) {
            if (level.label().equalsIgnoreCase(label)) {
                return level;
            }
        }
        throw new IllegalArgumentException("unknown noise level " + label + "; levels: " + String.join(", ", labels()));
    }
}
