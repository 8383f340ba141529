#include "io/drawn_outline.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "geometry/polygon.hpp"

namespace blockdem {
namespace {

double orientation(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

// p lies on segment a-b, given that it is on the line through them.
bool within(Vec2 a, Vec2 b, Vec2 p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Whether the closed segments p1-p2 and q1-q2 share a point (exact orientation signs: an
// outline drawn in CAD has its shared points exactly equal).
bool segments_meet(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
    const double d1 = orientation(q1, q2, p1), d2 = orientation(q1, q2, p2);
    const double d3 = orientation(p1, p2, q1), d4 = orientation(p1, p2, q2);
    if (((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))) return true;
    return (d1 == 0.0 && within(q1, q2, p1)) || (d2 == 0.0 && within(q1, q2, p2)) || (d3 == 0.0 && within(p1, p2, q1)) ||
           (d4 == 0.0 && within(p1, p2, q2));
}

// No area, relative to the square of the outline's size, so that the test does not depend on
// the drawing's units.
constexpr double area_tolerance = 1e-12;

// The diagonal of the outline's bounding box.
double outline_size(const std::vector<Vec2>& v) {
    Vec2 lo = v[0], hi = v[0];
    for (const Vec2& p : v) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    return length(hi - lo);
}

// Whether every corner lies on the line through the first corner and the corner farthest from
// it (the triangle each makes with them has no area).
bool on_one_line(const std::vector<Vec2>& v, double size) {
    const Vec2 far = *std::max_element(v.begin(), v.end(), [&](Vec2 p, Vec2 q) { return length(p - v[0]) < length(q - v[0]); });
    return std::all_of(v.begin(), v.end(), [&](Vec2 p) {
        return !(std::abs(orientation(v[0], far, p)) > area_tolerance * size * size);
    });
}

std::string point_text(Vec2 p, const std::string& unit) { return fmt::format("({:.10g}, {:.10g}) {}", p.x, p.y, unit); }

}  // namespace

std::vector<Vec2> without_repeated_vertices(std::vector<Vec2> vertices) {
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    while (vertices.size() > 1 && vertices.front() == vertices.back()) vertices.pop_back();
    return vertices;
}

std::optional<std::string> drawn_outline_problem(const std::vector<Vec2>& v, const std::string& unit) {
    const std::size_t n = v.size();
    if (n < 3) return fmt::format("has {} distinct corner{}: a block needs at least 3", n, n == 1 ? "" : "s");
    if (n > max_outline_vertices)
        return fmt::format("has {} corners, more than the {} a block may have", n, max_outline_vertices);
    // Checked in this order so that each outline gets the message of what is wrong with it: a
    // self-crossing outline can have no net area (a symmetric bow tie), and corners on one
    // line fold back on themselves.
    const double size = outline_size(v);
    if (on_one_line(v, size)) return "has no area (its corners lie on one line)";
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = v[i], b = v[(i + 1) % n], c = v[(i + 2) % n];
        if (orientation(a, b, c) == 0.0 && dot(b - a, c - b) < 0.0)
            return fmt::format("folds back on itself at its corner {} {}", (i + 1) % n, point_text(b, unit));
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // neighbours through the closing corner
            if (segments_meet(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n]))
                return fmt::format("crosses itself: its edge from corner {} {} meets its edge from corner {} {} (a block "
                                   "outline must be a simple polygon)",
                                   i, point_text(v[i], unit), j, point_text(v[j], unit));
        }
    // A simple polygon off one line has an area; this catches a sliver rounding leaves of one.
    if (!(std::abs(signed_area(v)) > area_tolerance * size * size)) return "has no area (its corners lie almost on one line)";
    return std::nullopt;
}

}  // namespace blockdem
