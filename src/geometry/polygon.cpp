#include "geometry/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace blockdem {

double signed_area(const std::vector<Vec2>& v) {
    double twice = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) twice += cross(v[i], v[(i + 1) % v.size()]);
    return 0.5 * twice;
}

// Triangle fan about the first vertex, shifted to it to keep round-off small for far-away polygons.
PolygonProperties polygon_properties(const std::vector<Vec2>& v) {
    const Vec2 origin = v.front();
    double area = 0.0;
    Vec2 first_moment;        // integral of r dA about origin [m^3]
    double second_moment = 0.0; // integral of |r|^2 dA about origin [m^4]
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
        const Vec2 e1 = v[i] - origin;
        const Vec2 e2 = v[i + 1] - origin;
        const double tri_area = 0.5 * cross(e1, e2);
        area += tri_area;
        first_moment += (tri_area / 3.0) * (e1 + e2);
        second_moment += (tri_area / 6.0) * (dot(e1, e1) + dot(e1, e2) + dot(e2, e2));
    }
    PolygonProperties p;
    p.area_m2 = area;
    const Vec2 c = (1.0 / area) * first_moment;
    p.centroid_m = origin + c;
    p.polar_moment_m4 = second_moment - area * dot(c, c);  // parallel-axis theorem
    return p;
}

namespace {

// convexity_problem, naming vertex i of v as number(i) (the position in the user's list).
template <class Number>
std::optional<std::string> convexity_problem_numbered(const std::vector<Vec2>& v, Number number) {
    const std::size_t n = v.size();
    if (n < 3) return fmt::format("a polygon needs at least 3 vertices, got {}", n);
    double size = 0.0;
    for (const Vec2& p : v) size = std::max({size, std::abs(p.x - v[0].x), std::abs(p.y - v[0].y)});
    const double tiny = 1e-12 * std::max(size, 1e-300);
    for (std::size_t i = 0; i < n; ++i)
        if (length(v[(i + 1) % n] - v[i]) <= tiny)
            return fmt::format("vertices {} and {} coincide at ({}, {}) m", std::min(number(i), number((i + 1) % n)),
                               std::max(number(i), number((i + 1) % n)), v[i].x, v[i].y);
    const double area = signed_area(v);
    if (area == 0.0)
        return "the vertices enclose no area (they lie on one line)";
    if (area < 0.0) return "vertices run clockwise; list them counter-clockwise";
    double turning = 0.0;  // total turning angle: exactly 2 pi for a simple convex polygon
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 e0 = v[(i + 1) % n] - v[i];
        const Vec2 e1 = v[(i + 2) % n] - v[(i + 1) % n];
        const double turn = cross(e0, e1);
        if (turn <= 1e-12 * length(e0) * length(e1))
            return fmt::format("not strictly convex at vertex {} ({}, {}) m: the corner turns the wrong way or is straight",
                               number((i + 1) % n), v[(i + 1) % n].x, v[(i + 1) % n].y);
        turning += std::atan2(turn, dot(e0, e1));
    }
    if (turning > 2.0 * std::numbers::pi + 1e-6) return "the polygon crosses itself (it winds more than once)";
    return std::nullopt;
}

}  // namespace

std::optional<std::string> convexity_problem(const std::vector<Vec2>& v) {
    return convexity_problem_numbered(v, [](std::size_t i) { return i; });
}

std::optional<std::string> listed_vertices_problem(const std::vector<Vec2>& listed) {
    if (!(signed_area(listed) < 0.0)) return convexity_problem(listed);
    const std::size_t n = listed.size();
    const auto problem = convexity_problem_numbered(counter_clockwise(listed), [n](std::size_t i) { return n - 1 - i; });
    if (!problem) return std::nullopt;
    return *problem + " (the vertices are listed clockwise, which is accepted: they are checked in reverse order, and "
                      "vertex numbers are positions in the list as written, from 0)";
}

std::vector<Vec2> counter_clockwise(std::vector<Vec2> vertices) {
    if (signed_area(vertices) < 0.0) std::reverse(vertices.begin(), vertices.end());
    return vertices;
}

std::vector<Vec2> rectangle_vertices(double width_m, double height_m, Vec2 center_m, double rotation_rad) {
    const Rotation r = Rotation::from_angle(rotation_rad);
    const double hw = 0.5 * width_m;
    const double hh = 0.5 * height_m;
    std::vector<Vec2> out;
    for (Vec2 corner : {Vec2{-hw, -hh}, Vec2{hw, -hh}, Vec2{hw, hh}, Vec2{-hw, hh}}) out.push_back(center_m + r.apply(corner));
    return out;
}

double least_width(const std::vector<Vec2>& vertices) {
    double least = INFINITY;
    const std::size_t n = vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 edge = vertices[(i + 1) % n] - vertices[i];
        const double edge_length = length(edge);
        if (!(edge_length > 0.0)) continue;
        double farthest = 0.0;
        for (const Vec2 v : vertices) farthest = std::max(farthest, std::abs(cross(edge, v - vertices[i])) / edge_length);
        least = std::min(least, farthest);
    }
    return least;
}

}  // namespace blockdem
