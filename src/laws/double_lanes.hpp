#pragma once
// Two doubles side by side, one a contact point, and 3-D vectors of them: the 3-D law takes two
// points of a pair at once (world/step_3d.cpp), so that each operation of its straight-line
// arithmetic serves both. Why: the law's Vec3 arithmetic compiled to scalar operations, one
// point at a time, with a register copy for about every other one; two lanes (GCC and Clang's
// vector extension, 16 bytes: SSE2 on x86-64, NEON on AArch64) halve the operations a point.
// Each lane rounds as the scalar expression written the same way, so a lane's result is the
// point's own, whatever the other lane holds.
#include <cmath>

#include "geometry/vec3.hpp"

namespace blockdem {

using DoubleLanes = double __attribute__((vector_size(16)));  ///< two doubles, one a point
using LaneMask = long long __attribute__((vector_size(16)));  ///< all bits set in a lane where true

inline DoubleLanes lanes(double value) { return DoubleLanes{value, value}; }
inline DoubleLanes lanes(double first, double second) { return DoubleLanes{first, second}; }
inline DoubleLanes select(LaneMask where, DoubleLanes yes, DoubleLanes no) { return where ? yes : no; }
/// std::max(a, b) in each lane: (a < b) ? b : a. On x86-64 one maxpd, (b > a) ? b : a (the
/// vector extension's own select compiles to four instructions).
inline DoubleLanes lane_max(DoubleLanes a, DoubleLanes b) {
#if defined(__SSE2__) && defined(__GNUC__) && !defined(__clang__)
    return __builtin_ia32_maxpd(b, a);
#else
    return a < b ? b : a;
#endif
}
inline DoubleLanes lane_sqrt(DoubleLanes a) { return DoubleLanes{std::sqrt(a[0]), std::sqrt(a[1])}; }
/// Whether the mask holds in both lanes.
inline bool both(LaneMask m) { return (m[0] & m[1]) != 0; }
inline double lane_sum(DoubleLanes a) { return a[0] + a[1]; }

struct Vec3Lanes {
    DoubleLanes x, y, z;
};

inline Vec3Lanes lanes(Vec3 first, Vec3 second) {
    return {DoubleLanes{first.x, second.x}, DoubleLanes{first.y, second.y}, DoubleLanes{first.z, second.z}};
}
inline Vec3Lanes lanes(Vec3 value) { return {lanes(value.x), lanes(value.y), lanes(value.z)}; }
inline Vec3 lane(const Vec3Lanes& v, int i) { return {v.x[i], v.y[i], v.z[i]}; }
inline Vec3 lane_sum(const Vec3Lanes& v) { return {lane_sum(v.x), lane_sum(v.y), lane_sum(v.z)}; }

inline Vec3Lanes operator+(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3Lanes operator-(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3Lanes operator*(DoubleLanes s, const Vec3Lanes& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3Lanes& operator+=(Vec3Lanes& a, const Vec3Lanes& b) {
    a.x += b.x;
    a.y += b.y;
    a.z += b.z;
    return a;
}
inline DoubleLanes dot(const Vec3Lanes& a, const Vec3Lanes& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3Lanes cross(const Vec3Lanes& a, const Vec3Lanes& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace blockdem
