#pragma once
// Unit quaternions for orientations: q = (w, x, y, z) turns the body frame into the world frame,
// r_world = q r_body q*. Composition q1 * q2 applies q2 first. Rotation vectors (axis times angle
// [rad]) map to quaternions exactly (exp), which is how the integrator turns a body by omega dt.
#include <cmath>

#include "geometry/matrix_3d.hpp"
#include "geometry/vec3.hpp"

namespace blockdem {

struct Quaternion {
    double w = 1.0;
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

constexpr Quaternion operator*(Quaternion a, Quaternion b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
constexpr Quaternion conjugate(Quaternion q) { return {q.w, -q.x, -q.y, -q.z}; }
inline Quaternion normalized(Quaternion q) {
    const double l = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / l, q.x / l, q.y / l, q.z / l};
}

/// q at unit length when it is within round-off of it, as the product of two unit quaternions is:
/// |q|^2 = 1 + e, and the Newton step (3 - |q|^2) / 2 for 1/sqrt(|q|^2) is off by 3 e^2 / 8, below
/// 1e-30 for e of round-off's 1e-15, so no square root nor division is needed (the drift of each
/// body, each step). Further from unit length (|e| > 1e-8) it is normalized as by normalized().
inline Quaternion renormalized(Quaternion q) {
    const double n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    if (std::abs(n2 - 1.0) > 1e-8) return normalized(q);
    const double s = 1.5 - 0.5 * n2;
    return {s * q.w, s * q.x, s * q.y, s * q.z};
}

/// The vector v (body frame) turned into the world frame by the unit quaternion q.
constexpr Vec3 rotate(Quaternion q, Vec3 v) {
    // v + 2 w (u x v) + 2 u x (u x v), u the vector part: fewer products than q v q*.
    const Vec3 u{q.x, q.y, q.z};
    const Vec3 t = 2.0 * cross(u, v);
    return v + q.w * t + cross(u, t);
}
/// The world vector v expressed in the body frame of q.
constexpr Vec3 rotate_inverse(Quaternion q, Vec3 v) { return rotate(conjugate(q), v); }

/// The rotation by |v| [rad] about v: exp of the rotation vector, exact for any angle.
inline Quaternion from_rotation_vector(Vec3 v) {
    const double angle = length(v);
    if (angle < 1e-8) {
        // sin(a/2)/a = 1/2 - a^2/48 + ...: the series to round-off below 1e-8.
        const double half = 0.5 - angle * angle / 48.0;
        return normalized(Quaternion{1.0 - angle * angle / 8.0, half * v.x, half * v.y, half * v.z});
    }
    const double s = std::sin(0.5 * angle) / angle;
    return {std::cos(0.5 * angle), s * v.x, s * v.y, s * v.z};
}

/// The rotation vector (axis times angle [rad], angle in [0, pi]) of the unit quaternion q.
inline Vec3 rotation_vector(Quaternion q) {
    if (q.w < 0.0) q = {-q.w, -q.x, -q.y, -q.z};  // the same rotation, the shorter way round
    const double s = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (s < 1e-12) return {2.0 * q.x, 2.0 * q.y, 2.0 * q.z};
    const double angle = 2.0 * std::atan2(s, q.w);
    return (angle / s) * Vec3{q.x, q.y, q.z};
}

/// The rotation matrix of the unit quaternion q (columns: the body axes in the world frame).
constexpr Matrix3d rotation_matrix(Quaternion q) {
    return Matrix3d::from_columns(rotate(q, {1, 0, 0}), rotate(q, {0, 1, 0}), rotate(q, {0, 0, 1}));
}

/// The same matrix by the quaternion's products, 1 - 2 (y^2 + z^2), 2 (x y - w z), ... (equal to
/// rotation_matrix to round-off): 9 products and 12 sums, where turning the three axes costs
/// about 90 operations (a product by an axis's zero is still a product). The 3-D step poses a
/// body with one of these: turning a vector by a matrix is 15 operations, by q about 30.
constexpr Matrix3d rotation_matrix_by_products(Quaternion q) {
    const double x2 = 2.0 * q.x, y2 = 2.0 * q.y, z2 = 2.0 * q.z;
    const double xx = q.x * x2, yy = q.y * y2, zz = q.z * z2;
    const double xy = q.x * y2, xz = q.x * z2, yz = q.y * z2;
    const double wx = q.w * x2, wy = q.w * y2, wz = q.w * z2;
    return {{{{1.0 - (yy + zz), xy - wz, xz + wy}, {xy + wz, 1.0 - (xx + zz), yz - wx}, {xz - wy, yz + wx, 1.0 - (xx + yy)}}}};
}

/// The transpose of a rotation matrix times v: v turned back into the body frame.
constexpr Vec3 transpose_times(const Matrix3d& r, Vec3 v) {
    return {r.m[0][0] * v.x + r.m[1][0] * v.y + r.m[2][0] * v.z, r.m[0][1] * v.x + r.m[1][1] * v.y + r.m[2][1] * v.z,
            r.m[0][2] * v.x + r.m[1][2] * v.y + r.m[2][2] * v.z};
}

/// The unit quaternion of a rotation matrix (det +1), by the largest of the four squares
/// (Shepperd 1978), so that no division is by a small number.
inline Quaternion from_rotation_matrix(const Matrix3d& r) {
    const auto& m = r.m;
    const double t = m[0][0] + m[1][1] + m[2][2];
    Quaternion q;
    if (t >= m[0][0] && t >= m[1][1] && t >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + t);
        q = {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
    } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        q = {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
    } else if (m[1][1] >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
        q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
        q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
    }
    return normalized(q);
}

}  // namespace blockdem
