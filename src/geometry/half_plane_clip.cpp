#include "geometry/half_plane_clip.hpp"

#include <cmath>

namespace blockdem {

double polygon_area(const std::vector<Vec2>& v) {
    double twice = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) twice += cross(v[i], v[(i + 1) % v.size()]);
    return 0.5 * twice;
}

ConvexSplit split_convex(const std::vector<Vec2>& polygon, const HalfPlane& line) {
    ConvexSplit out;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p = polygon[i];
        const Vec2 q = polygon[(i + 1) % n];
        const double dp = dot(line.normal, p) - line.offset;
        const double dq = dot(line.normal, q) - line.offset;
        if (dp <= 0.0) out.below.push_back(p);
        if (dp >= 0.0) out.above.push_back(p);
        if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
            // Interpolate from the same end whichever side asks, so both parts get the same point.
            const bool from_p = dp < 0.0;
            const Vec2 a = from_p ? p : q;
            const Vec2 b = from_p ? q : p;
            const double da = from_p ? dp : dq;
            const double db = from_p ? dq : dp;
            const Vec2 x = a + (da / (da - db)) * (b - a);
            out.below.push_back(x);
            out.above.push_back(x);
        }
    }
    if (out.below.size() < 3) out.below.clear();
    if (out.above.size() < 3) out.above.clear();
    return out;
}

std::vector<Vec2> clip_convex(const std::vector<Vec2>& polygon, const HalfPlane& keep) {
    return split_convex(polygon, keep).below;
}

std::optional<std::vector<Vec2>> tidy_convex_polygon(const std::vector<Vec2>& polygon, double tolerance_m) {
    std::vector<Vec2> v;
    for (const Vec2& p : polygon)
        if (v.empty() || length(p - v.back()) > tolerance_m) v.push_back(p);
    while (v.size() > 1 && length(v.front() - v.back()) <= tolerance_m) v.pop_back();
    // Drop straight (or backward, from round-off) corners until none is left.
    bool changed = true;
    while (changed && v.size() >= 3) {
        changed = false;
        for (std::size_t i = 0; i < v.size() && v.size() >= 3; ++i) {
            const Vec2 prev = v[(i + v.size() - 1) % v.size()];
            const Vec2 next = v[(i + 1) % v.size()];
            const Vec2 e0 = v[i] - prev;
            const Vec2 e1 = next - v[i];
            if (cross(e0, e1) <= 1e-9 * length(e0) * length(e1)) {
                v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
            }
        }
    }
    if (v.size() < 3 || !(polygon_area(v) > 0.0)) return std::nullopt;
    return v;
}

}  // namespace blockdem
