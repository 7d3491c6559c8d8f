package org.usarsim.wss.world;

/**
 * A rigid transform of SDF: a rotation and a translation, in metres. SDF's {@code <pose>x y z roll
 * pitch yaw</pose>} turns about the fixed x, then y, then z axes (R = Rz(yaw) Ry(pitch) Rx(roll)),
 * as gz-math's Quaternion from Euler angles does. Immutable.
 */
final class Pose {

    static final Pose IDENTITY = new Pose(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, 0, 0, 0);

    /** Row-major 3 x 3. */
    private final double[] r;
    private final double tx;
    private final double ty;
    private final double tz;

    private Pose(double[] r, double tx, double ty, double tz) {
        this.r = r;
        this.tx = tx;
        this.ty = ty;
        this.tz = tz;
    }

    /** The pose at (x, y, z) turned by roll, pitch and yaw, in radians. */
    static Pose euler(double x, double y, double z, double roll, double pitch, double yaw) {
        double cr = Math.cos(roll);
        double sr = Math.sin(roll);
        double cp = Math.cos(pitch);
        double sp = Math.sin(pitch);
        double cy = Math.cos(yaw);
        double sy = Math.sin(yaw);
        return new Pose(new double[] {
            cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
            sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
            -sp, cp * sr, cp * cr}, x, y, z);
    }

    /** The pose at (x, y, z) turned by the quaternion (qx, qy, qz, qw), normalised here; null when it is all zeros. */
    static Pose quaternion(double x, double y, double z, double qx, double qy, double qz, double qw) {
        double n = Math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
        if (!(n > 0)) {
            return null;
        }
        double a = qx / n;
        double b = qy / n;
        double c = qz / n;
        double w = qw / n;
        return new Pose(new double[] {
            1 - 2 * (b * b + c * c), 2 * (a * b - c * w), 2 * (a * c + b * w),
            2 * (a * b + c * w), 1 - 2 * (a * a + c * c), 2 * (b * c - a * w),
            2 * (a * c - b * w), 2 * (b * c + a * w), 1 - 2 * (a * a + b * b)}, x, y, z);
    }

    /** The child's pose, given relative to this one, in this one's parent frame. */
    Pose then(Pose child) {
        double[] m = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[3 * i + j] = r[3 * i] * child.r[j] + r[3 * i + 1] * child.r[3 + j] + r[3 * i + 2] * child.r[6 + j];
            }
        }
        double[] t = apply(child.tx, child.ty, child.tz);
        return new Pose(m, t[0], t[1], t[2]);
    }

    /** The point (x, y, z) of this frame in the parent frame: {x, y, z}. */
    double[] apply(double x, double y, double z) {
        return new double[] {
            r[0] * x + r[1] * y + r[2] * z + tx,
            r[3] * x + r[4] * y + r[5] * z + ty,
            r[6] * x + r[7] * y + r[8] * z + tz};
    }
}
