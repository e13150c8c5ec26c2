package org.proactiverobotics.engine.scenario.localisation;

import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.CommonOps_DDRM;

/**
 * An extended Kalman filter over the robot's pose and its odometry's scale: state (x, y, heading,
 * scale) in metres, metres, radians and a pure number. It predicts from each wheel odometry
 * reading (the wheels' travel times the scale: wheels that slip roll further than the robot goes,
 * and the scale learns by how much) and corrects with whatever measures the pose: the inertial
 * unit's heading, a GPS fix, a scan matched against the map. Saved with its rule (the plain fields);
 * the matrices it works in are scratch, allocated once.
 */
final class PoseFilter {

    /** Each wheel's travel is known to this share of itself (slip, uneven floor): the prediction's noise. */
    static final double WHEEL_SIGMA_SHARE = 0.02;
    /** And to this much whatever the travel, metres (the encoder's resolution). */
    static final double WHEEL_SIGMA_M = 0.0005;
    /** The odometry's scale wanders by this much per metre travelled (tyres wear, the floor changes). */
    static final double SCALE_WANDER_PER_M = 0.002;
    /**
     * The odometry's scale at the start: rubber wheels on a hard indoor floor lose about 2 % of what
     * they roll (docs/sensors.md's standard configuration, what a calibration such as UMBmark
     * measures on a real robot); the filter learns the robot's own from the GPS or the scan.
     */
    static final double SCALE_PRIOR = 0.98;
    /** How far that scale is trusted at the start: wheels slip a few percent. */
    static final double SCALE_SIGMA = 0.03;

    private double x;
    private double y;
    private double yaw;
    private double scale = SCALE_PRIOR;
    /** The covariance, row by row (4 x 4). */
    private double[] p = new double[16];
    private boolean started;

    private transient Scratch s;

    /** The matrices a step works in, made once per filter (after a resume too). */
    private static final class Scratch {
        final DMatrixRMaj p = new DMatrixRMaj(4, 4);
        final DMatrixRMaj f = new DMatrixRMaj(4, 4);
        final DMatrixRMaj g = new DMatrixRMaj(4, 2);
        final DMatrixRMaj q = new DMatrixRMaj(2, 2);
        final DMatrixRMaj tmp44 = new DMatrixRMaj(4, 4);
        final DMatrixRMaj tmp42 = new DMatrixRMaj(4, 2);
        final DMatrixRMaj gq = new DMatrixRMaj(4, 4);
        // measurement updates, by dimension 1, 2, 3
        final DMatrixRMaj[] h = {new DMatrixRMaj(1, 4), new DMatrixRMaj(2, 4), new DMatrixRMaj(3, 4)};
        final DMatrixRMaj[] ph = {new DMatrixRMaj(4, 1), new DMatrixRMaj(4, 2), new DMatrixRMaj(4, 3)};
        final DMatrixRMaj[] sm = {new DMatrixRMaj(1, 1), new DMatrixRMaj(2, 2), new DMatrixRMaj(3, 3)};
        final DMatrixRMaj[] r = {new DMatrixRMaj(1, 1), new DMatrixRMaj(2, 2), new DMatrixRMaj(3, 3)};
        final DMatrixRMaj[] sInv = {new DMatrixRMaj(1, 1), new DMatrixRMaj(2, 2), new DMatrixRMaj(3, 3)};
        final DMatrixRMaj[] k = {new DMatrixRMaj(4, 1), new DMatrixRMaj(4, 2), new DMatrixRMaj(4, 3)};
        final DMatrixRMaj[] kh = {new DMatrixRMaj(4, 4), new DMatrixRMaj(4, 4), new DMatrixRMaj(4, 4)};
        final DMatrixRMaj[] innovation = {new DMatrixRMaj(1, 1), new DMatrixRMaj(2, 1), new DMatrixRMaj(3, 1)};
        final DMatrixRMaj[] dx = {new DMatrixRMaj(4, 1), new DMatrixRMaj(4, 1), new DMatrixRMaj(4, 1)};
    }

    /**
     * Starts the filter at a pose.
     *
     * @param xM         x, metres
     * @param yM         y, metres
     * @param yawRad     heading, radians
     * @param sigmaM     how well the position is known, metres (one standard deviation)
     * @param sigmaYawRad how well the heading is known, radians
     */
    void start(double xM, double yM, double yawRad, double sigmaM, double sigmaYawRad) {
        x = xM;
        y = yM;
        yaw = wrap(yawRad);
        scale = SCALE_PRIOR;
        p = new double[16];
        p[0] = sigmaM * sigmaM;
        p[5] = sigmaM * sigmaM;
        p[10] = sigmaYawRad * sigmaYawRad;
        p[15] = SCALE_SIGMA * SCALE_SIGMA;
        started = true;
    }

    boolean started() {
        return started;
    }

    /**
     * Moves the pose by one odometry reading (a differential drive: the arc at the middle heading).
     *
     * @param leftM  the left wheel's travel, metres
     * @param rightM the right wheel's travel, metres
     * @param axleM  the distance between the wheels, metres
     */
    void predict(double leftM, double rightM, double axleM) {
        Scratch m = scratch();
        double mean = (leftM + rightM) / 2;
        double turn = (rightM - leftM) / axleM;
        double d = scale * mean;
        double dYaw = scale * turn;
        double mid = yaw + dYaw / 2;
        double c = Math.cos(mid);
        double sn = Math.sin(mid);

        m.f.zero();
        m.f.set(0, 0, 1);
        m.f.set(1, 1, 1);
        m.f.set(2, 2, 1);
        m.f.set(3, 3, 1);
        m.f.set(0, 2, -d * sn);
        m.f.set(1, 2, d * c);
        m.f.set(0, 3, mean * c - d * sn * turn / 2);
        m.f.set(1, 3, mean * sn + d * c * turn / 2);
        m.f.set(2, 3, turn);

        double half = scale / 2;
        double bend = d * scale / (2 * axleM);
        m.g.set(0, 0, half * c + bend * sn);
        m.g.set(0, 1, half * c - bend * sn);
        m.g.set(1, 0, half * sn - bend * c);
        m.g.set(1, 1, half * sn + bend * c);
        m.g.set(2, 0, -scale / axleM);
        m.g.set(2, 1, scale / axleM);
        m.g.set(3, 0, 0);
        m.g.set(3, 1, 0);
        double sl = WHEEL_SIGMA_SHARE * Math.abs(leftM) + WHEEL_SIGMA_M;
        double sr = WHEEL_SIGMA_SHARE * Math.abs(rightM) + WHEEL_SIGMA_M;
        m.q.set(0, 0, sl * sl);
        m.q.set(1, 1, sr * sr);

        x += d * c;
        y += d * sn;
        yaw = wrap(yaw + dYaw);

        // P = F P F' + G Q G' (+ the scale's wander)
        m.p.setData(p);
        CommonOps_DDRM.mult(m.f, m.p, m.tmp44);
        CommonOps_DDRM.multTransB(m.tmp44, m.f, m.p);
        CommonOps_DDRM.mult(m.g, m.q, m.tmp42);
        CommonOps_DDRM.multTransB(m.tmp42, m.g, m.gq);
        CommonOps_DDRM.addEquals(m.p, m.gq);
        double wander = SCALE_WANDER_PER_M * Math.abs(mean);
        m.p.add(3, 3, wander * wander);
        keep(m.p);
    }

    /**
     * Corrects the heading with the inertial unit's reading.
     *
     * @param yawRad   the reading, radians
     * @param sigmaRad its standard deviation, radians
     */
    void correctYaw(double yawRad, double sigmaRad) {
        Scratch m = scratch();
        DMatrixRMaj h = m.h[0];
        h.zero();
        h.set(0, 2, 1);
        m.innovation[0].set(0, 0, wrap(yawRad - yaw));
        update(m, 0, sigmaRad * sigmaRad, null);
    }

    /**
     * Corrects the position with a GPS fix.
     *
     * @param xM     the fix's x, metres
     * @param yM     the fix's y, metres
     * @param sigmaM its standard deviation on each axis, metres
     */
    void correctPosition(double xM, double yM, double sigmaM) {
        Scratch m = scratch();
        DMatrixRMaj h = m.h[1];
        h.zero();
        h.set(0, 0, 1);
        h.set(1, 1, 1);
        m.innovation[1].set(0, 0, xM - x);
        m.innovation[1].set(1, 0, yM - y);
        update(m, 1, sigmaM * sigmaM, null);
    }

    /**
     * Corrects the pose with a pose measured whole (a scan matched against the map).
     *
     * @param xM         measured x, metres
     * @param yM         measured y, metres
     * @param yawRad     measured heading, radians
     * @param covariance its covariance, 3 x 3 row by row (x, y, heading)
     */
    void correctPose(double xM, double yM, double yawRad, double[] covariance) {
        Scratch m = scratch();
        DMatrixRMaj h = m.h[2];
        h.zero();
        h.set(0, 0, 1);
        h.set(1, 1, 1);
        h.set(2, 2, 1);
        m.innovation[2].set(0, 0, xM - x);
        m.innovation[2].set(1, 0, yM - y);
        m.innovation[2].set(2, 0, wrap(yawRad - yaw));
        update(m, 2, 0, covariance);
    }

    /** The Kalman update with the measurement set up in the scratch's H and innovation of this dimension - 1; R diagonal or full. */
    private void update(Scratch m, int dim, double diagonalR, double[] fullR) {
        DMatrixRMaj h = m.h[dim];
        DMatrixRMaj sMat = m.sm[dim];
        m.p.setData(p);
        CommonOps_DDRM.multTransB(m.p, h, m.ph[dim]); // P H'
        CommonOps_DDRM.mult(h, m.ph[dim], sMat); // H P H'
        int n = dim + 1;
        DMatrixRMaj r = m.r[dim];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                r.set(i, j, fullR != null ? fullR[i * n + j] : (i == j ? diagonalR : 0));
            }
        }
        CommonOps_DDRM.addEquals(sMat, r);
        if (!CommonOps_DDRM.invert(sMat, m.sInv[dim])) {
            return; // a measurement that says nothing (singular): keep the prediction
        }
        CommonOps_DDRM.mult(m.ph[dim], m.sInv[dim], m.k[dim]); // K = P H' S^-1
        CommonOps_DDRM.mult(m.k[dim], m.innovation[dim], m.dx[dim]);
        x += m.dx[dim].get(0);
        y += m.dx[dim].get(1);
        yaw = wrap(yaw + m.dx[dim].get(2));
        scale += m.dx[dim].get(3);
        // P = (I - K H) P (I - K H)' + K R K' (Joseph's form: stays symmetric and positive where (I - K H) P drifts)
        CommonOps_DDRM.mult(m.k[dim], h, m.kh[dim]);
        CommonOps_DDRM.scale(-1, m.kh[dim]);
        for (int i = 0; i < 4; i++) {
            m.kh[dim].add(i, i, 1);
        }
        CommonOps_DDRM.mult(m.kh[dim], m.p, m.tmp44);
        CommonOps_DDRM.multTransB(m.tmp44, m.kh[dim], m.p);
        CommonOps_DDRM.mult(m.k[dim], r, m.ph[dim]);
        CommonOps_DDRM.multTransB(m.ph[dim], m.k[dim], m.tmp44);
        CommonOps_DDRM.addEquals(m.p, m.tmp44);
        keep(m.p);
    }

    /** Stores the covariance, symmetric (rounding makes it drift apart otherwise). */
    private void keep(DMatrixRMaj m) {
        for (int i = 0; i < 4; i++) {
            for (int j = i; j < 4; j++) {
                double v = (m.get(i, j) + m.get(j, i)) / 2;
                p[i * 4 + j] = v;
                p[j * 4 + i] = v;
            }
        }
    }

    private Scratch scratch() {
        if (s == null) {
            s = new Scratch();
        }
        return s;
    }

    double x() {
        return x;
    }

    double y() {
        return y;
    }

    double yaw() {
        return yaw;
    }

    double scale() {
        return scale;
    }

    /** @return the covariance's entry (row, column): 0 x, 1 y, 2 heading, 3 scale */
    double covariance(int row, int column) {
        return p[row * 4 + column];
    }

    /** @return an angle in (-pi, pi] */
    static double wrap(double a) {
        if (a > -Math.PI && a <= Math.PI) {
            return a;
        }
        double w = Math.IEEEremainder(a, 2 * Math.PI);
        return w <= -Math.PI ? w + 2 * Math.PI : w;
    }
}
