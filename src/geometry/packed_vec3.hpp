#pragma once
// A 3-D vector with its x and y in the two lanes of one 16-byte register and its z apart, for the
// per-body arithmetic of the 3-D step (the pose in world/step_3d.cpp, the kick in
// dynamics/rigid_rotation_3d.hpp). Why: the build has no -march, so Vec3's arithmetic is scalar
// SSE2, one operation an instruction; here a sum or product takes two where Vec3's takes three,
// and x and y load and store as one 16-byte move. Each lane rounds as the scalar expression
// written the same way (laws/double_lanes.hpp), so every result is Vec3's to the bit.
#include <cmath>
#include <cstddef>
#include <cstring>

#include "geometry/matrix_3d.hpp"
#include "geometry/vec3.hpp"
#include "laws/double_lanes.hpp"

namespace blockdem {

struct PackedVec3 {
    DoubleLanes xy;
    double z;
};
inline PackedVec3 packed(Vec3 v) { return {lanes(v.x, v.y), v.z}; }
/// v read from memory: x and y by one 16-byte load (the first 16 bytes of a Vec3).
inline PackedVec3 load(const Vec3& v) {
    PackedVec3 p;
    std::memcpy(&p.xy, static_cast<const void*>(&v), sizeof(p.xy));
    p.z = v.z;
    return p;
}
inline PackedVec3 operator+(const PackedVec3& a, const PackedVec3& b) { return {a.xy + b.xy, a.z + b.z}; }
inline PackedVec3 operator-(const PackedVec3& a, const PackedVec3& b) { return {a.xy - b.xy, a.z - b.z}; }
inline PackedVec3 operator-(const PackedVec3& a) { return {-a.xy, -a.z}; }
inline PackedVec3 operator*(double s, const PackedVec3& a) { return {lanes(s) * a.xy, s * a.z}; }
inline PackedVec3 hadamard(const PackedVec3& a, const PackedVec3& b) { return {a.xy * b.xy, a.z * b.z}; }
/// a.x b.x + a.y b.y + a.z b.z, summed in dot(Vec3, Vec3)'s order.
inline double dot(const PackedVec3& a, const PackedVec3& b) {
    const DoubleLanes p = a.xy * b.xy;
    return p[0] + p[1] + a.z * b.z;
}
inline void store(const PackedVec3& a, Vec3* to) {
    std::memcpy(static_cast<void*>(to), &a.xy, sizeof(a.xy));  // x and y, the first 16 bytes of a Vec3 (trivially copyable)
    to->z = a.z;
}
inline PackedVec3 absolute(const PackedVec3& a) { return {lane_max(a.xy, -a.xy), std::abs(a.z)}; }

/// The rotation matrix by columns, packed: R v = c0 v.x + c1 v.y + c2 v.z, summed in Matrix3d's
/// order, so the same bits as rotation * v.
struct PackedRotation {
    PackedVec3 columns[3];
};
inline PackedRotation packed(const Matrix3d& r) {
    return {{packed(r.column(0)), packed(r.column(1)), packed(r.column(2))}};
}
inline PackedVec3 operator*(const PackedRotation& r, Vec3 v) {
    return v.x * r.columns[0] + v.y * r.columns[1] + v.z * r.columns[2];
}
inline PackedVec3 operator*(const PackedRotation& r, const PackedVec3& v) {
    return v.xy[0] * r.columns[0] + v.xy[1] * r.columns[1] + v.z * r.columns[2];
}

/// R^T v = r0 v.x + r1 v.y + r2 v.z with r_k the rows of R (contiguous in Matrix3d: each row's
/// first two entries one 16-byte load), summed in transpose_times's order: the same bits.
inline PackedVec3 transpose_times(const Matrix3d& r, const PackedVec3& v) {
    const auto row = [&](std::size_t k) {
        PackedVec3 p;
        std::memcpy(&p.xy, r.m[k].data(), sizeof(p.xy));
        p.z = r.m[k][2];
        return p;
    };
    return v.xy[0] * row(0) + v.xy[1] * row(1) + v.z * row(2);
}

}  // namespace blockdem
