#include "geometry/convex_decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/half_plane_clip.hpp"

namespace blockdem {
namespace {

using Piece = std::vector<std::size_t>;  // corner indices into the outline, counter-clockwise

bool inside_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
    return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
}

std::vector<Piece> ear_clip(const std::vector<Vec2>& v) {
    std::vector<std::size_t> left(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) left[i] = i;
    std::vector<Piece> triangles;
    while (left.size() > 3) {
        bool clipped = false;
        for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
            const std::size_t ia = left[(k + left.size() - 1) % left.size()];
            const std::size_t ib = left[k];
            const std::size_t ic = left[(k + 1) % left.size()];
            if (cross(v[ib] - v[ia], v[ic] - v[ib]) <= 0.0) continue;  // reflex or straight: not an ear
            bool empty = true;
            for (std::size_t other : left)
                if (other != ia && other != ib && other != ic && inside_triangle(v[other], v[ia], v[ib], v[ic]))
                    empty = false;
            if (!empty) continue;
            triangles.push_back({ia, ib, ic});
            left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
            clipped = true;
        }
        if (!clipped) throw std::invalid_argument("the region's outline crosses itself (no ear left to clip)");
    }
    triangles.push_back(left);
    return triangles;
}

std::vector<Vec2> corners(const Piece& piece, const std::vector<Vec2>& v) {
    std::vector<Vec2> out;
    for (std::size_t i : piece) out.push_back(v[i]);
    return out;
}

// The merge of two pieces sharing the edge (u, v) of a (which b holds as (v, u)), or {} if none.
Piece merged(const Piece& a, const Piece& b) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const std::size_t u = a[i];
        const std::size_t w = a[(i + 1) % a.size()];
        for (std::size_t j = 0; j < b.size(); ++j) {
            if (b[j] != w || b[(j + 1) % b.size()] != u) continue;
            Piece out;
            for (std::size_t k = 0; k < a.size(); ++k) out.push_back(a[(i + 1 + k) % a.size()]);  // w ... u
            for (std::size_t k = 2; k < b.size(); ++k) out.push_back(b[(j + k) % b.size()]);      // after u, before w
            return out;
        }
    }
    return {};
}

}  // namespace

bool is_convex(const std::vector<Vec2>& v) {
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Vec2 e0 = v[(i + 1) % v.size()] - v[i];
        const Vec2 e1 = v[(i + 2) % v.size()] - v[(i + 1) % v.size()];
        if (cross(e0, e1) < -1e-12 * length(e0) * length(e1)) return false;
    }
    return true;
}

std::vector<std::vector<Vec2>> convex_decomposition(std::vector<Vec2> polygon) {
    if (polygon.size() < 3) throw std::invalid_argument("a region needs at least 3 corners");
    const double area = polygon_area(polygon);
    if (area == 0.0) throw std::invalid_argument("the region has zero area");
    if (area < 0.0) std::reverse(polygon.begin(), polygon.end());
    if (is_convex(polygon)) return {polygon};

    std::vector<Piece> pieces = ear_clip(polygon);
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t i = 0; i < pieces.size() && !changed; ++i)
            for (std::size_t j = i + 1; j < pieces.size() && !changed; ++j) {
                Piece m = merged(pieces[i], pieces[j]);
                if (m.empty() || !is_convex(corners(m, polygon))) continue;
                pieces[i] = std::move(m);
                pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(j));
                changed = true;
            }
    }
    std::vector<std::vector<Vec2>> out;
    for (const Piece& p : pieces) out.push_back(corners(p, polygon));
    return out;
}

}  // namespace blockdem
