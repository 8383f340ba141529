#pragma once
// A 2D vector of doubles, with the few operations the physics needs.
// Conventions (docs/physics.md): x horizontal, y up; angles counter-clockwise positive.
#include <cmath>

namespace blockdem {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
constexpr Vec2& operator+=(Vec2& a, Vec2 b) { a.x += b.x; a.y += b.y; return a; }
constexpr Vec2& operator-=(Vec2& a, Vec2 b) { a.x -= b.x; a.y -= b.y; return a; }
constexpr bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z component of the 3D cross product a x b.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// w x r for an angular velocity w about z: the velocity of a point at r.
constexpr Vec2 cross(double w, Vec2 r) { return {-w * r.y, w * r.x}; }
/// The vector turned 90 degrees counter-clockwise.
constexpr Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
// sqrt(dot) rather than hypot: lengths here are metres, far from overflow, and hypot costs
// several times more in the time step.
inline double length(Vec2 a) { return std::sqrt(dot(a, a)); }
/// |a.x| + |a.y| >= length(a): an upper bound with no square root.
inline double norm_bound(Vec2 a) { return std::abs(a.x) + std::abs(a.y); }
inline Vec2 normalized(Vec2 a) { double l = length(a); return {a.x / l, a.y / l}; }

/// A rotation by angle [rad], stored as its cosine and sine.
struct Rotation {
    double c = 1.0;
    double s = 0.0;
    static Rotation from_angle(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }
    constexpr Vec2 apply(Vec2 v) const { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
};

}  // namespace blockdem
