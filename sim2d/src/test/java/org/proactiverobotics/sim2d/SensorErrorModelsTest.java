package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** The errors beyond white noise: their statistics over many seeded draws, and where each one acts. */
class SensorErrorModelsTest {

    private static final double DT_S = 0.032;
    private static final int CHAINS = 4000;

    private static SensorNoise only(RangeError range, GpsBias bias, HeadingDrift drift, WheelSlip slip) {
        return new SensorNoise(0.0, 0.0, 0.0, range, bias, drift, slip, true);
    }

    @Test
    void gpsBiasWandersWithTheConfiguredSigmaAndCorrelationTime() {
        GpsBias bias = new GpsBias(0.05, 1.0);
        SensorNoise noise = only(RangeError.NONE, bias, HeadingDrift.NONE, WheelSlip.NONE);
        int lag = 31; // 0.992 s: one correlation time
        double[] start = new double[CHAINS];
        double[] later = new double[CHAINS];
        for (int c = 0; c < CHAINS; c++) {
            SensorErrors e = new SensorErrors(noise, 1000 + c, DT_S);
            for (int k = 1; k <= 200; k++) { // forget the start
                e.advance(k);
            }
            start[c] = e.gpsBiasXM();
            for (int k = 201; k <= 200 + lag; k++) {
                e.advance(k);
            }
            later[c] = e.gpsBiasXM();
        }
        assertThat(sd(start)).isCloseTo(0.05, within(0.0025));
        assertThat(sd(later)).isCloseTo(0.05, within(0.0025));
        assertThat(correlation(start, later)).isCloseTo(Math.exp(-lag * DT_S / 1.0), within(0.05));
        // Step to step the bias barely moves: it wanders, it does not jitter.
        SensorErrors e = new SensorErrors(noise, 5, DT_S);
        double before = e.gpsBiasXM();
        e.advance(1);
        assertThat(Math.abs(e.gpsBiasXM() - before)).isLessThan(0.05 * 0.5);
    }

    @Test
    void gpsBiasShowsInTheReadingsAndWhiteNoiseIsUnchanged() {
        WorldSpec world = Worlds.empty(5.0, 0.5, -0.25, 0.0);
        Simulation white = new Simulation(world, new SensorNoise(0.01, 0.0, 0.0));
        Simulation biased = new Simulation(world, new SensorNoise(0.01, 0.0, 0.0, RangeError.NONE,
                new GpsBias(0.03, 60.0), HeadingDrift.NONE, WheelSlip.NONE, true));
        for (int k = 0; k < 50; k++) {
            double[] w = white.robot().gps().getValues();
            double[] b = biased.robot().gps().getValues();
            SensorErrors errors = new SensorErrors(biased.noise(), world.seed(), DT_S);
            for (int j = 1; j <= k; j++) {
                errors.advance(j);
            }
            // Reading = truth + bias + the very same white draw as without the bias.
            assertThat(b[0] - w[0]).isCloseTo(errors.gpsBiasXM(), within(1e-12));
            assertThat(b[1] - w[1]).isCloseTo(errors.gpsBiasYM(), within(1e-12));
            white.step();
            biased.step();
        }
    }

    @Test
    void headingDriftGrowsLinearlyWithTheGyroBiasAndAsTheSquareRootOfTimeWithTheRandomWalk() {
        double biasSigma = Math.toRadians(0.01);
        double arw = Math.toRadians(0.05);
        int steps = 1000; // 32 s
        double t = steps * DT_S;
        double[] biasOnly = new double[CHAINS];
        double[] walkOnly = new double[CHAINS];
        for (int c = 0; c < CHAINS; c++) {
            SensorErrors b = new SensorErrors(only(RangeError.NONE, GpsBias.NONE, new HeadingDrift(biasSigma, 0.0),
                    WheelSlip.NONE), 77 + c, DT_S);
            SensorErrors w = new SensorErrors(only(RangeError.NONE, GpsBias.NONE, new HeadingDrift(0.0, arw),
                    WheelSlip.NONE), 77 + c, DT_S);
            for (int k = 1; k <= steps; k++) {
                b.advance(k);
                w.advance(k);
            }
            biasOnly[c] = b.headingErrorRad();
            walkOnly[c] = w.headingErrorRad();
        }
        assertThat(sd(biasOnly)).isCloseTo(biasSigma * t, within(0.05 * biasSigma * t));
        assertThat(sd(walkOnly)).isCloseTo(arw * Math.sqrt(t), within(0.05 * arw * Math.sqrt(t)));
    }

    @Test
    void headingDriftShowsInTheYaw() {
        WorldSpec world = Worlds.empty(5.0, 0.0, 0.0, 30.0);
        Simulation sim = new Simulation(world, only(RangeError.NONE, GpsBias.NONE,
                new HeadingDrift(Math.toRadians(0.5), 0.0), WheelSlip.NONE));
        Worlds.run(sim, 1000);
        double yaw = sim.robot().inertialUnit().getRollPitchYaw()[2];
        double error = Simulation.normalizeAngle(yaw - sim.groundTruth().headingRad());
        SensorErrors errors = new SensorErrors(sim.noise(), world.seed(), DT_S);
        for (int k = 1; k <= 1000; k++) {
            errors.advance(k);
        }
        assertThat(error).isCloseTo(errors.headingErrorRad(), within(1e-9)).isNotZero();
    }

    @Test
    void rangeErrorGrowsWithTheDistance() {
        double near = spreadOfFrontReading(0.3, 0.02);  // reads 0.18 m
        double far = spreadOfFrontReading(0.9, 0.02);   // reads 0.78 m
        assertThat(near).isCloseTo(0.02 * 0.18, within(0.1 * 0.02 * 0.18));
        assertThat(far).isCloseTo(0.02 * 0.78, within(0.1 * 0.02 * 0.78));
    }

    /** The standard deviation of the front sensor's reading over many steps of a robot standing faceX from a wall. */
    private static double spreadOfFrontReading(double faceX, double fraction) {
        int front = WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.indexOf(8.0);
        WorldSpec world = Worlds.empty(5.0, 0.0, 0.0, -8.0)
                .withObstacles(List.of(WorldSpec.Obstacle.box(faceX + 0.1, 0.0, 0.2, 3.0, 0.0)));
        Simulation sim = new Simulation(world, only(new RangeError(fraction), GpsBias.NONE, HeadingDrift.NONE,
                WheelSlip.NONE));
        double[] reads = new double[1500];
        for (int k = 0; k < reads.length; k++) {
            reads[k] = sim.robot().distanceSensors().get(front).getValue();
            sim.step();
        }
        return sd(reads);
    }

    @Test
    void wheelSlipShortensTheTravelByTheConfiguredFraction() {
        WorldSpec world = Worlds.empty(10.0, -4.0, 0.0, 0.0);
        Simulation firm = new Simulation(world);
        Simulation slipping = new Simulation(world, only(RangeError.NONE, GpsBias.NONE, HeadingDrift.NONE,
                new WheelSlip(0.10, 0.02)));
        for (Simulation s : List.of(firm, slipping)) {
            s.robot().setWheelSpeeds(0.3, 0.3);
            Worlds.run(s, 500);
        }
        double ratio = slipping.groundTruth().distanceM() / firm.groundTruth().distanceM();
        assertThat(ratio).isCloseTo(0.90, within(0.005));
        // The encoders count what the wheels rolled, as commanded: the body's shortfall is odometry's error.
        assertThat(slipping.robot().odometer().getTravelM()).containsExactly(firm.robot().odometer().getTravelM());
        // A motion error, not a sensor's: the GPS (no noise of its own) reads where the robot really is.
        assertThat(slipping.robot().gps().getValues()[0]).isEqualTo(slipping.groundTruth().x());
    }

    @Test
    void withoutAFixTheGpsReadsNaN() {
        Simulation sim = new Simulation(Worlds.empty(5.0, 1.0, 1.0, 0.0), SensorNoise.SMALL.withoutGps());
        assertThat(sim.robot().gps().hasFix()).isFalse();
        assertThat(sim.robot().gps().getValues()).containsExactly(Double.NaN, Double.NaN);
        sim.step();
        assertThat(sim.robot().gps().getValues()).containsExactly(Double.NaN, Double.NaN);
        assertThat(new Simulation(Worlds.empty(5.0, 1.0, 1.0, 0.0), SensorNoise.SMALL).robot().gps().hasFix()).isTrue();
    }

    @Test
    void allErrorsTogetherAreDeterministicAndFollowTheSeed() {
        SensorNoise all = new SensorNoise(0.01, 0.03, 0.0005, new RangeError(0.01), new GpsBias(0.03, 60.0),
                new HeadingDrift(1e-4, 1e-4), new WheelSlip(0.02, 0.01), true);
        WorldSpec world = Worlds.empty(5.0, 0.0, 0.0, 0.0);
        assertThat(readings(world, all)).isEqualTo(readings(world, all));
        WorldSpec reseeded = new WorldSpec(world.name(), world.timeStepMs(), world.maxSimTimeS(), world.seed() + 1,
                world.arena(), world.robot(), world.obstacles(), world.checkpoints(), world.checkpointRadiusM(),
                world.rechargeStation(), world.battery());
        assertThat(readings(reseeded, all)).isNotEqualTo(readings(world, all));
    }

    /** Every reading and the true pose, as raw bits, while the robot turns and drives for 400 steps. */
    private static List<Long> readings(WorldSpec world, SensorNoise noise) {
        Simulation sim = new Simulation(world, noise);
        sim.robot().setWheelSpeeds(0.2, 0.3);
        List<Long> out = new ArrayList<>();
        for (int k = 0; k < 400; k++) {
            sim.step();
            for (double v : sim.robot().gps().getValues()) {
                out.add(Double.doubleToRawLongBits(v));
            }
            out.add(Double.doubleToRawLongBits(sim.robot().inertialUnit().getRollPitchYaw()[2]));
            for (DistanceSensor s : sim.robot().distanceSensors()) {
                out.add(Double.doubleToRawLongBits(s.getValue()));
            }
            out.add(Double.doubleToRawLongBits(sim.groundTruth().x()));
            out.add(Double.doubleToRawLongBits(sim.groundTruth().y()));
        }
        return out;
    }

    @Test
    void smallNoiseIsTheWhiteNoiseOfBeforeDrawForDraw() {
        WorldSpec world = Worlds.empty(5.0, 0.3, -0.2, 20.0)
                .withObstacles(List.of(WorldSpec.Obstacle.box(0.9, 0.0, 0.2, 3.0, 0.0)));
        Simulation truth = new Simulation(world);
        Simulation small = new Simulation(world, SensorNoise.SMALL);
        for (Simulation s : List.of(truth, small)) {
            s.robot().setWheelSpeeds(0.1, 0.15);
        }
        for (long step = 0; step < 200; step++) {
            double[] gps = small.robot().gps().getValues();
            double[] exact = truth.robot().gps().getValues();
            assertThat(gps[0]).isEqualTo(exact[0] + 0.01 * SensorNoise.gaussian(world.seed(), step, 0));
            assertThat(gps[1]).isEqualTo(exact[1] + 0.01 * SensorNoise.gaussian(world.seed(), step, 1));
            double yaw = truth.robotBody().getTransform().getRotationAngle();
            assertThat(small.robot().inertialUnit().getRollPitchYaw()[2]).isEqualTo(
                    Simulation.normalizeAngle(yaw + Math.toRadians(0.5) * SensorNoise.gaussian(world.seed(), step, 2)));
            for (int i = 0; i < 12; i++) {
                DistanceSensor ray = small.robot().distanceSensors().get(i);
                double d = truth.robot().distanceSensors().get(i).getValue() + 0.01 * SensorNoise.gaussian(world.seed(), step, 3 + i);
                assertThat(ray.getValue()).isEqualTo(Math.max(0.0, Math.min(ray.getRangeM(), d)));
            }
            truth.step();
            small.step();
        }
    }

    @Test
    void badFiguresAreRefused() {
        assertThatThrownBy(() -> new GpsBias(0.03, 0.0)).hasMessageContaining("correlationTimeS");
        assertThatThrownBy(() -> new WheelSlip(1.0, 0.0)).hasMessageContaining("below 1");
        assertThatThrownBy(() -> new RangeError(-0.01)).hasMessageContaining("fractionOfRange");
        assertThatThrownBy(() -> new HeadingDrift(Double.NaN, 0.0)).hasMessageContaining("biasSigmaRadPerS");
    }

    private static double sd(double[] v) {
        double mean = 0.0;
        for (double x : v) {
            mean += x;
        }
        mean /= v.length;
        double ss = 0.0;
        for (double x : v) {
            ss += (x - mean) * (x - mean);
        }
        return Math.sqrt(ss / (v.length - 1));
    }

    private static double correlation(double[] a, double[] b) {
        double ma = 0.0;
        double mb = 0.0;
        for (int i = 0; i < a.length; i++) {
            ma += a[i];
            mb += b[i];
        }
        ma /= a.length;
        mb /= b.length;
        double sab = 0.0;
        double saa = 0.0;
        double sbb = 0.0;
        for (int i = 0; i < a.length; i++) {
            sab += (a[i] - ma) * (b[i] - mb);
            saa += (a[i] - ma) * (a[i] - ma);
            sbb += (b[i] - mb) * (b[i] - mb);
        }
        return sab / Math.sqrt(saa * sbb);
    }
}
