#include "geometry/outline.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "geometry/convex_decomposition.hpp"
#include "geometry/polygon.hpp"

namespace blockdem {
namespace {

// Distance from p to the segment from s to e [m].
double distance_to_segment(Vec2 p, Vec2 s, Vec2 e) {
    const Vec2 d = e - s;
    const double t = std::clamp(dot(p - s, d) / dot(d, d), 0.0, 1.0);
    return length(p - (s + t * d));
}

// True when the open segments p0-p1 and q0-q1 cross at one interior point of each.
bool segments_cross(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
    const double d0 = cross(q1 - q0, p0 - q0), d1 = cross(q1 - q0, p1 - q0);
    const double d2 = cross(p1 - p0, q0 - p0), d3 = cross(p1 - p0, q1 - p0);
    return ((d0 > 0.0 && d1 < 0.0) || (d0 < 0.0 && d1 > 0.0)) && ((d2 > 0.0 && d3 < 0.0) || (d2 < 0.0 && d3 > 0.0));
}

const char* const keyhole_note =
    ": the outline touches itself there. A body is one outline without holes; a hole cut in through a slit (a "
    "keyhole) is not supported: split the body in two at the hole, or leave the hole out";

// outline_problem for a non-convex outline, naming vertex i of v as number(i).
template <class Number>
std::optional<std::string> concave_outline_problem(const std::vector<Vec2>& v, Number number) {
    const std::size_t n = v.size();
    double size = 0.0;
    for (const Vec2& p : v) size = std::max({size, std::abs(p.x - v[0].x), std::abs(p.y - v[0].y)});
    // (The same round-off scale as convexity_problem's coinciding vertices.)
    const double tiny = 1e-12 * std::max(size, 1e-300);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            if (length(v[j] - v[i]) > tiny) continue;
            const std::size_t lo = std::min(number(i), number(j)), hi = std::max(number(i), number(j));
            if (j == i + 1 || (i == 0 && j == n - 1))
                return fmt::format("vertices {} and {} coincide at ({}, {}) m", lo, hi, v[i].x, v[i].y);
            return fmt::format("vertices {} and {} coincide at ({}, {}) m{}", lo, hi, v[i].x, v[i].y, keyhole_note);
        }
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 e0 = v[(i + 1) % n] - v[i];
        const Vec2 e1 = v[(i + 2) % n] - v[(i + 1) % n];
        if (std::abs(cross(e0, e1)) > 1e-12 * length(e0) * length(e1)) continue;
        const std::size_t k = (i + 1) % n;
        if (dot(e0, e1) > 0.0)
            return fmt::format("straight corner at vertex {} ({}, {}) m: remove the vertex", number(k), v[k].x, v[k].y);
        return fmt::format("the outline folds back on itself at vertex {} ({}, {}) m", number(k), v[k].x, v[k].y);
    }
    // Every vertex against every edge it does not end, then every pair of edges that share no
    // corner (outlines are tens of corners: n^2 is nothing next to a run).
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t j1 = (j + 1) % n;
            if (j == k || j1 == k || distance_to_segment(v[k], v[j], v[j1]) > tiny) continue;
            return fmt::format("vertex {} ({}, {}) m lies on the edge from vertex {} to vertex {}{}", number(k), v[k].x,
                               v[k].y, number(j), number(j1), keyhole_note);
        }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
            const std::size_t i1 = (i + 1) % n, j1 = (j + 1) % n;
            if (!segments_cross(v[i], v[i1], v[j], v[j1])) continue;
            return fmt::format("the edge from vertex {} to vertex {} crosses the edge from vertex {} to vertex {}: the "
                               "outline crosses itself",
                               number(i), number(i1), number(j), number(j1));
        }
    if (signed_area(v) == 0.0) return "the vertices enclose no area";
    if (signed_area(v) < 0.0) return "vertices run clockwise; list them counter-clockwise";
    return std::nullopt;
}

}  // namespace

std::optional<std::string> outline_problem(const std::vector<Vec2>& v) {
    if (v.size() < 3 || is_convex(v)) return convexity_problem(v);
    return concave_outline_problem(v, [](std::size_t i) { return i; });
}

std::optional<std::string> listed_outline_problem(const std::vector<Vec2>& listed) {
    if (listed.size() < 3 || is_convex(counter_clockwise(listed))) return listed_vertices_problem(listed);
    if (!(signed_area(listed) < 0.0)) return outline_problem(listed);
    const std::size_t n = listed.size();
    const auto problem = concave_outline_problem(counter_clockwise(listed), [n](std::size_t i) { return n - 1 - i; });
    if (!problem) return std::nullopt;
    return *problem + " (the vertices are listed clockwise, which is accepted: vertex numbers are positions in the list "
                      "as written, from 0)";
}

std::vector<std::vector<Vec2>> outline_parts(const std::vector<Vec2>& outline) {
    if (is_convex(outline)) return {outline};
    std::vector<std::vector<Vec2>> parts = convex_pieces_cut_at_reflex_corners(outline);
    // Merged pieces may keep a corner of the outline that is straight inside the piece (where a
    // removed diagonal continued an edge): the narrow phase wants strictly convex polygons.
    for (std::vector<Vec2>& part : parts) {
        for (std::size_t k = 0; k < part.size() && part.size() > 3;) {
            const std::size_t n = part.size();
            const Vec2 e0 = part[k] - part[(k + n - 1) % n];
            const Vec2 e1 = part[(k + 1) % n] - part[k];
            if (cross(e0, e1) <= 1e-12 * length(e0) * length(e1)) part.erase(part.begin() + static_cast<std::ptrdiff_t>(k));
            else ++k;
        }
    }
    return parts;
}

std::vector<Vec2> convex_hull(const Vec2* points, std::size_t count) {
    std::vector<Vec2> p(points, points + count);
    std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (p.size() < 3) return p;
    std::vector<Vec2> hull(2 * p.size());
    std::size_t k = 0;
    auto add = [&](Vec2 q, std::size_t floor) {
        while (k >= floor && cross(hull[k - 1] - hull[k - 2], q - hull[k - 1]) <= 0.0) --k;
        hull[k++] = q;
    };
    for (const Vec2& q : p) add(q, 2);                                                  // lower chain
    for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) add(p[i], lower);       // upper chain
    hull.resize(k - 1);  // (the last point is the first)
    return hull;
}

}  // namespace blockdem
