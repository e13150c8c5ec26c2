package org.proactiverobotics.app.mission;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.proactiverobotics.sim2d.GpsBias;
import org.proactiverobotics.sim2d.HeadingDrift;
import org.proactiverobotics.sim2d.RangeError;
import org.proactiverobotics.sim2d.SensorNoise;
import org.proactiverobotics.sim2d.WheelSlip;

/**
 * The sensor noise levels of {@code --noise} on {@code run}, {@code robot} and {@code sweep}, drawn from the
 * world's {@code seed}. {@link #NONE} is the run of the world file alone. Each figure and its source (a data
 * sheet or a standard configuration) is in docs/sensors.md.
 */
public enum NoiseLevel {
    /** Perfect sensors. */
    NONE(SensorNoise.NONE),
    /** 1 cm on each GPS coordinate, 0.5° on the yaw, 1 cm on each distance ray. */
    SMALL(SensorNoise.SMALL),
    /**
     * Real sensors' errors: an RTK GPS (1 cm white) whose fix wanders (3 cm bias, 60 s correlation), a
     * gyro-integrated heading that drifts (MPU-6050 class) with 2° white noise, a lidar error of 0.5 mm plus 1 %
     * of the distance (RPLIDAR A1), and wheels that slip 2 % ± 1 %.
     */
    REALISTIC(realistic()),
    /** {@link #REALISTIC} without any GPS: no absolute position at all, as indoors. */
    INDOOR(realistic().withoutGps());

    private final SensorNoise noise;

    NoiseLevel(SensorNoise noise) {
        this.noise = noise;
    }

    /** @return the standard deviations the simulator draws with */
    public SensorNoise sensorNoise() {
        return noise;
    }

    /** @return the name on the command line and in results.csv: none, small, realistic, indoor */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The figures of {@link #REALISTIC}; docs/sensors.md gives each one's source. */
    private static SensorNoise realistic() {
        return new SensorNoise(
                0.01,                                  // GPS white, m: u-blox ZED-F9P RTK, 0.01 m CEP
                Math.toRadians(2.0),                   // yaw white, rad: a consumer fused heading
                0.0005,                                // distance white, m: RPLIDAR A1 resolution, < 0.5 mm
                new RangeError(0.01),                  // RPLIDAR A1: < 1 % of the distance
                new GpsBias(0.03, 60.0),               // a wandering RTK fix: 3 cm, 60 s
                new HeadingDrift(Math.toRadians(0.005), Math.toRadians(0.005)), // MPU-6050: rad/s, rad/√s
                new WheelSlip(0.02, 0.01),             // rubber wheels on a hard floor
                true);
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
