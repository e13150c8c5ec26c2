package org.proactiverobotics.app;

import org.proactiverobotics.app.mission.NoiseLevel;
import picocli.CommandLine.Option;

/** {@code --noise} of {@code run} and {@code robot}: seeded sensor noise. A picocli mixin. */
public final class NoiseOption {

    @Option(names = "--noise", paramLabel = "LEVEL", defaultValue = "none",
            description = "Seeded sensor noise on GPS, inertial unit and distance sensors, drawn from the world's seed:"
                    + " none, small, realistic (with GPS bias, heading drift, range error, wheel slip) or indoor"
                    + " (realistic without GPS). Default: ${DEFAULT-VALUE} (the world file alone).")
    private String noise;

    /** @return what is wrong with the option, or null */
    public String problem() {
        try {
            NoiseLevel.of(noise);
            return null;
        } catch (IllegalArgumentException e) {
            return "--noise: " + e.getMessage();
        }
    }

    /** @return the level asked for (check {@link #problem()} first) */
    public NoiseLevel level() {
        return NoiseLevel.of(noise);
    }
}
