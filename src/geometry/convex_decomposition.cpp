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

// Hertel-Mehlhorn: removes every diagonal whose two pieces merge into a convex polygon.
void merge_where_convex(std::vector<Piece>& pieces, const std::vector<Vec2>& polygon) {
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
}

double turn(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - b); }  // > 0: a left turn at b

// A corner turning right beyond round-off (a straight corner, left where a cut met an edge,
// needs no cut: the caller removes it).
bool is_reflex(Vec2 before, Vec2 corner, Vec2 after) {
    return turn(before, corner, after) < -1e-12 * length(corner - before) * length(after - corner);
}

// True when the segment from corner k of piece p to corner m lies inside p: inside the angle
// at both ends, and touching no edge nor corner on its way (O'Rourke's diagonal test).
bool is_inside_diagonal(const Piece& p, const std::vector<Vec2>& v, std::size_t k, std::size_t m) {
    const std::size_t n = p.size();
    auto in_angle = [&](std::size_t at, std::size_t to) {
        const Vec2 before = v[p[(at + n - 1) % n]], corner = v[p[at]], after = v[p[(at + 1) % n]], target = v[p[to]];
        if (turn(before, corner, after) > 0.0)
            return cross(target - corner, before - corner) > 0.0 && cross(after - corner, target - corner) > 0.0;
        return !(cross(target - corner, before - corner) <= 0.0 && cross(after - corner, target - corner) <= 0.0);
    };
    if (!in_angle(k, m) || !in_angle(m, k)) return false;
    const Vec2 a = v[p[k]], b = v[p[m]];
    for (std::size_t e = 0; e < n; ++e) {
        const std::size_t e1 = (e + 1) % n;
        if (e == k || e == m || e1 == k || e1 == m) continue;
        const Vec2 c = v[p[e]], d = v[p[e1]];
        const double d0 = cross(b - a, c - a), d1 = cross(b - a, d - a);
        const double d2 = cross(d - c, a - c), d3 = cross(d - c, b - c);
        if (((d0 > 0.0) != (d1 > 0.0) || d0 == 0.0 || d1 == 0.0) && ((d2 > 0.0) != (d3 > 0.0) || d2 == 0.0 || d3 == 0.0))
            return false;  // crosses or touches the edge
    }
    return true;
}

// The two pieces of p on either side of the diagonal from corner k to corner m (k < m).
std::pair<Piece, Piece> split(const Piece& p, std::size_t k, std::size_t m) {
    Piece first(p.begin() + static_cast<std::ptrdiff_t>(k), p.begin() + static_cast<std::ptrdiff_t>(m) + 1);
    Piece second(p.begin() + static_cast<std::ptrdiff_t>(m), p.end());
    second.insert(second.end(), p.begin(), p.begin() + static_cast<std::ptrdiff_t>(k) + 1);
    return {first, second};
}

// How many of the diagonal's two ends it makes convex on both sides (a reflex corner split
// into two angles of at most 180 degrees: a cut that goes on along an edge leaves a straight
// corner, which the caller removes).
int corners_resolved(const Piece& p, const std::vector<Vec2>& v, std::size_t k, std::size_t m) {
    const std::size_t n = p.size();
    auto resolves = [&](std::size_t at, std::size_t to) {
        const Vec2 before = v[p[(at + n - 1) % n]], corner = v[p[at]], after = v[p[(at + 1) % n]], target = v[p[to]];
        return is_reflex(before, corner, after) && turn(before, corner, target) >= 0.0 && turn(target, corner, after) >= 0.0;
    };
    return (resolves(k, m) ? 1 : 0) + (resolves(m, k) ? 1 : 0);
}

// Where the line of an edge at reflex corner k, carried on through k into the piece, first meets
// the piece's boundary: the edge hit (index e: from corner e to e + 1) and the point. None when
// it meets a corner (the diagonal to that corner is a candidate already) or nothing.
struct EdgeHit {
    std::size_t edge = 0;
    Vec2 point;
    double distance = INFINITY;  ///< [m] from corner k
};

EdgeHit extension_hit(const Piece& p, const std::vector<Vec2>& v, std::size_t k, Vec2 direction) {
    const std::size_t n = p.size();
    const Vec2 from = v[p[k]];
    EdgeHit best;
    for (std::size_t e = 0; e < n; ++e) {
        const std::size_t e1 = (e + 1) % n;
        if (e == k || e1 == k) continue;
        const Vec2 c = v[p[e]], d = v[p[e1]];
        const double denominator = cross(direction, d - c);
        if (denominator == 0.0) continue;  // parallel
        const double t = cross(c - from, d - c) / denominator;  // along direction
        const double u = cross(c - from, direction) / denominator;  // along the edge
        if (!(t > 0.0) || u < 0.0 || u > 1.0) continue;
        const double distance = t * length(direction);
        if (distance < best.distance) best = {e, from + t * direction, distance};
    }
    // (Within round-off of a corner: that corner's diagonal is the cut.)
    if (std::isfinite(best.distance)) {
        const double tiny = 1e-9 * length(v[p[(best.edge + 1) % n]] - v[p[best.edge]]);
        if (length(best.point - v[p[best.edge]]) <= tiny || length(best.point - v[p[(best.edge + 1) % n]]) <= tiny)
            best.distance = INFINITY;
    }
    return best;
}

// The two pieces of p on either side of the cut from corner k to a new corner s on edge e.
std::pair<Piece, Piece> split_at_new_corner(const Piece& p, std::size_t k, std::size_t e, std::size_t s) {
    const std::size_t n = p.size();
    Piece first, second;
    for (std::size_t i = k;; i = (i + 1) % n) {  // k, ..., e, then s
        first.push_back(p[i]);
        if (i == e) break;
    }
    first.push_back(s);
    second.push_back(s);
    for (std::size_t i = (e + 1) % n;; i = (i + 1) % n) {  // s, e + 1, ..., k
        second.push_back(p[i]);
        if (i == k) break;
    }
    return {first, second};
}

// Cuts a piece from its reflex corners until every piece is convex. Candidate cuts: diagonals
// to other corners, and the line of an edge at the reflex corner carried on to the boundary (a
// new corner there: an L is cut into its two rectangles, so its sole stays one edge of one part).
// Each cut is the one that makes most of its ends convex; among cuts that make both ends convex,
// the one whose ends have the fewest such cuts (so that a groove's corner, which has one, is
// paired before its partner is taken: a keyed brick gives 5 rectangles); then the shortest.
// v gains the new corners.
void cut_at_reflex_corners(const Piece& p, std::vector<Vec2>& v, std::vector<Piece>& out) {
    const std::size_t n = p.size();
    auto is_reflex_at = [&](std::size_t k) { return is_reflex(v[p[(k + n - 1) % n]], v[p[k]], v[p[(k + 1) % n]]); };
    auto is_candidate = [&](std::size_t k, std::size_t m) {
        return m != k && m != (k + 1) % n && (m + 1) % n != k && is_inside_diagonal(p, v, k, m);
    };
    // How many diagonals that make both ends convex each corner has.
    std::vector<int> double_cuts(n, 0);
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t m = k + 1; m < n && is_reflex_at(k); ++m)
            if (is_reflex_at(m) && is_candidate(k, m) && corners_resolved(p, v, k, m) == 2) {
                ++double_cuts[k];
                ++double_cuts[m];
            }
    int best_resolved = 0;
    int best_degree = 0;
    double best_length = INFINITY;
    std::size_t best_k = 0, best_m = 0;
    EdgeHit best_hit;  // set when the best cut ends on an edge
    for (std::size_t k = 0; k < n; ++k) {
        if (!is_reflex_at(k)) continue;
        const Vec2 before = v[p[(k + n - 1) % n]], corner = v[p[k]], after = v[p[(k + 1) % n]];
        for (std::size_t m = 0; m < n; ++m) {
            if (!is_candidate(k, m)) continue;
            const int resolved = corners_resolved(p, v, k, m);
            const int degree = resolved == 2 ? double_cuts[k] + double_cuts[m] : 0;
            const double cut = length(v[p[m]] - v[p[k]]);
            if (resolved > best_resolved ||
                (resolved == best_resolved && (degree < best_degree || (degree == best_degree && cut < best_length)))) {
                best_resolved = resolved;
                best_degree = degree;
                best_length = cut;
                best_k = k;
                best_m = m;
                best_hit = EdgeHit{};
            }
        }
        // An extension leaves a straight angle on one side and the rest (below 180 degrees,
        // the corner being reflex) on the other: it makes its corner convex.
        for (const Vec2 direction : {corner - before, corner - after}) {
            const EdgeHit hit = extension_hit(p, v, k, direction);
            if (!std::isfinite(hit.distance)) continue;
            if (1 > best_resolved || (1 == best_resolved && hit.distance < best_length)) {
                best_resolved = 1;
                best_degree = 0;
                best_length = hit.distance;
                best_k = k;
                best_hit = hit;
            }
        }
    }
    if (best_resolved == 0) {
        out.push_back(p);  // convex (no reflex corner), or no cut found: left to the caller's check
        return;
    }
    std::pair<Piece, Piece> pieces;
    if (std::isfinite(best_hit.distance)) {
        v.push_back(best_hit.point);
        pieces = split_at_new_corner(p, best_k, best_hit.edge, v.size() - 1);
    } else {
        pieces = split(p, std::min(best_k, best_m), std::max(best_k, best_m));
    }
    cut_at_reflex_corners(pieces.first, v, out);
    cut_at_reflex_corners(pieces.second, v, out);
}

}  // namespace

std::vector<std::vector<Vec2>> convex_pieces_cut_at_reflex_corners(std::vector<Vec2> polygon) {
    if (polygon.size() < 3) throw std::invalid_argument("a polygon needs at least 3 corners");
    const double area = polygon_area(polygon);
    if (area == 0.0) throw std::invalid_argument("the polygon has zero area");
    if (area < 0.0) std::reverse(polygon.begin(), polygon.end());
    if (is_convex(polygon)) return {polygon};
    Piece all(polygon.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    std::vector<Piece> pieces;
    cut_at_reflex_corners(all, polygon, pieces);  // (appends the new corners to polygon)
    merge_where_convex(pieces, polygon);
    std::vector<std::vector<Vec2>> out;
    for (const Piece& p : pieces) out.push_back(corners(p, polygon));
    return out;
}

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
    merge_where_convex(pieces, polygon);
    std::vector<std::vector<Vec2>> out;
    for (const Piece& p : pieces) out.push_back(corners(p, polygon));
    return out;
}

}  // namespace blockdem
