package org.usarsim.wss.ros;

/**
 * A rigid transform: a translation and a rotation (a unit quaternion), as a ROS
 * {@code geometry_msgs/Transform} or {@code Pose} gives them. {@code a.then(b)} is the pose of
 * b's child in a's parent frame: {@code t = a.t + a.R b.t}, {@code q = a.q b.q}.
 */
record Transform(double x, double y, double z, double qx, double qy, double qz, double qw) {

    static final Transform IDENTITY = new Transform(0, 0, 0, 0, 0, 0, 1);

    /**
     * A translation and a rotation read from a message: the quaternion is normalised; one of
     * length zero (or not finite) is refused.
     */
    static Transform of(JsonNode translation, JsonNode rotation) throws JsonException {
        double qx = rotation.get("x").number();
        double qy = rotation.get("y").number();
        double qz = rotation.get("z").number();
        double qw = rotation.get("w").number();
        double length = Math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
        if (!(length > 1e-9) || !Double.isFinite(length)) {
            throw rotation.problem("not a rotation: a quaternion of length " + length);
        }
        return new Transform(translation.get("x").number(), translation.get("y").number(), translation.get("z").number(),
                qx / length, qy / length, qz / length, qw / length);
    }

    /** This transform followed by {@code inner} (a transform expressed in this one's child frame). */
    Transform then(Transform inner) {
        double[] t = rotate(inner.x, inner.y, inner.z);
        return new Transform(x + t[0], y + t[1], z + t[2],
                qw * inner.qx + qx * inner.qw + qy * inner.qz - qz * inner.qy,
                qw * inner.qy - qx * inner.qz + qy * inner.qw + qz * inner.qx,
                qw * inner.qz + qx * inner.qy - qy * inner.qx + qz * inner.qw,
                qw * inner.qw - qx * inner.qx - qy * inner.qy - qz * inner.qz);
    }

    /** A vector turned by this rotation: v + 2w(u x v) + 2u x (u x v), u the quaternion's vector part. */
    double[] rotate(double vx, double vy, double vz) {
        double cx = qy * vz - qz * vy;
        double cy = qz * vx - qx * vz;
        double cz = qx * vy - qy * vx;
        double ccx = qy * cz - qz * cy;
        double ccy = qz * cx - qx * cz;
        double ccz = qx * cy - qy * cx;
        return new double[] {vx + 2 * (qw * cx + ccx), vy + 2 * (qw * cy + ccy), vz + 2 * (qw * cz + ccz)};
    }

    /** The rotation's angle about z (yaw), in radians. */
    double yaw() {
        return Math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz));
    }
}
