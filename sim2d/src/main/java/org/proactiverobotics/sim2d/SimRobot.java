package org.proactiverobotics.sim2d;

import java.util.List;

/**
 * The robot as its controller sees it, Webots-style: devices to read and two wheels to drive.
 * A differential drive: wheel speeds in metres per second, clamped to ±{@link #maxSpeedMps()}; the wheels
 * sit on the rim, so the axle is as wide as the robot. Readings reflect the state after the last step.
 */
public final class SimRobot {


    private final double radiusM;
    private final double maxSpeedMps;
    private final Gps gps;
    private final InertialUnit inertialUnit;
    private final List<DistanceSensor> distanceSensors;
    private final Battery battery;
    private final WheelOdometer odometer;
    private double leftMps;
    private double rightMps;

    SimRobot(WorldRobot owner, WorldSpec.Robot spec) {
        this.radiusM = spec.radiusM();
        this.maxSpeedMps = spec.maxSpeedMps();
        this.gps = new Gps(owner);
        this.inertialUnit = new InertialUnit(owner);
        DistanceSensor[] sensors = new DistanceSensor[spec.sensorAnglesDeg().size()];
        for (int i = 0; i < sensors.length; i++) {
            sensors[i] = new DistanceSensor(owner, i, Math.toRadians(spec.sensorAnglesDeg().get(i)), spec.sensorRangeM());
        }
        this.distanceSensors = List.of(sensors);
        this.battery = new Battery(owner);
        this.odometer = new WheelOdometer(owner);
    }

    /** @return the default distance sensors' angles relative to the heading, degrees, by index (a copy) */
    public static double[] sensorAnglesDeg() {
        return WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** @return the GPS */
    public Gps gps() {
        return gps;
    }

    /** @return the inertial unit */
    public InertialUnit inertialUnit() {
        return inertialUnit;
    }

    /** @return the distance sensors, by index (0 = rightmost, counter-clockwise) */
    public List<DistanceSensor> distanceSensors() {
        return distanceSensors;
    }

    /** @return the battery */
    public Battery battery() {
        return battery;
    }

    /** @return the wheel encoders */
    public WheelOdometer odometer() {
        return odometer;
    }

    /**
     * Sets both wheel speeds for the coming steps, each clamped to ±{@link #maxSpeedMps()}; NaN reads as 0.
     *
     * @param leftMps  left wheel, metres per second (positive forwards)
     * @param rightMps right wheel, metres per second (positive forwards)
     */
    public void setWheelSpeeds(double leftMps, double rightMps) {
        this.leftMps = clamp(leftMps);
        this.rightMps = clamp(rightMps);
    }

    private double clamp(double v) {
        if (Double.isNaN(v)) {
            return 0.0;
        }
        return Math.max(-maxSpeedMps, Math.min(maxSpeedMps, v));
    }

    /** @return the commanded left wheel speed after clamping, metres per second */
    public double leftSpeedMps() {
        return leftMps;
    }

    /** @return the commanded right wheel speed after clamping, metres per second */
    public double rightSpeedMps() {
        return rightMps;
    }

    /** @return the highest wheel speed, metres per second */
    public double maxSpeedMps() {
        return maxSpeedMps;
    }

    /** @return the body's radius, metres */
    public double radiusM() {
        return radiusM;
    }

    /** @return the distance between the wheels, metres (the robot's diameter) */
    public double axleWidthM() {
        return 2.0 * radiusM;
    }
}
