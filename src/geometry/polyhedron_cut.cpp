// Clipping a convex polyhedron by a plane (Sutherland-Hodgman on each face, the section as the
// cap) and a region cut into blocks by a list of planes; see polyhedron_cut.hpp for the rules.
#include "geometry/polyhedron_cut.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "geometry/vec2.hpp"

namespace blockdem {
namespace {

// A vertex's side of the plane: -1 below, 0 on it (within the tolerance), +1 above.
int side_of(double distance_m, double tolerance_m) {
    return distance_m > tolerance_m ? 1 : distance_m < -tolerance_m ? -1 : 0;
}

bool before(Vec3 a, Vec3 b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }

// Where the edge (a, b) crosses the plane, computed from the ends in one fixed order so that the
// two faces sharing the edge get the same point to the last bit.
Vec3 crossing(Vec3 a, Vec3 b, const Plane3d& plane) {
    if (before(b, a)) std::swap(a, b);
    const double da = dot(plane.normal, a) - plane.offset_m;
    const double db = dot(plane.normal, b) - plane.offset_m;
    return a + (da / (da - db)) * (b - a);
}

void add_distinct(std::vector<Vec3>& points, Vec3 p, double tolerance_m) {
    for (Vec3 q : points)
        if (length(p - q) <= tolerance_m) return;
    points.push_back(p);
}

// The corners of the points (all in one plane), counter-clockwise about the outward normal n:
// Andrew's monotone chain in a basis (u, v) of the plane with u x v = n; points on an edge of
// the hull are not corners.
std::vector<Vec3> cap_corners(const std::vector<Vec3>& points, Vec3 n, double tolerance_m) {
    const Vec3 helper = std::abs(n.x) < 0.6 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    const Vec3 u = normalized(cross(helper, n));
    const Vec3 v = cross(n, u);
    struct Planar {
        Vec2 p;
        Vec3 point;
    };
    std::vector<Planar> planar;
    for (Vec3 q : points) planar.push_back({{dot(q, u), dot(q, v)}, q});
    std::sort(planar.begin(), planar.end(),
              [](const Planar& a, const Planar& b) { return a.p.x < b.p.x || (a.p.x == b.p.x && a.p.y < b.p.y); });
    double size_m = 0.0;
    for (const Planar& q : planar) size_m = std::max(size_m, length(q.p - planar.front().p));
    const double area_tolerance_m2 = tolerance_m * size_m;
    const auto turns_left = [&](const Planar& o, const Planar& a, const Planar& b) {
        return cross(a.p - o.p, b.p - o.p) > area_tolerance_m2;
    };
    std::vector<Planar> hull(2 * planar.size() + 1);
    std::size_t k = 0;
    for (std::size_t i = 0; i < planar.size(); ++i) {
        while (k >= 2 && !turns_left(hull[k - 2], hull[k - 1], planar[i])) --k;
        hull[k++] = planar[i];
    }
    for (std::size_t i = planar.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && !turns_left(hull[k - 2], hull[k - 1], planar[i])) --k;
        hull[k++] = planar[i];
    }
    std::vector<Vec3> corners;
    for (std::size_t i = 0; i + 1 < k; ++i) corners.push_back(hull[i].point);
    return corners;
}

// One face clipped to the side `keep` (-1 or +1) of the plane: Sutherland-Hodgman, with the
// vertices on the plane kept and no crossing made at them.
std::vector<Vec3> clip_face(const std::vector<Vec3>& corners, const std::vector<int>& sides, int keep,
                            const Plane3d& plane) {
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const std::size_t j = (i + 1) % corners.size();
        if (sides[i] != -keep) out.push_back(corners[i]);
        if (sides[i] * sides[j] == -1) out.push_back(crossing(corners[i], corners[j], plane));
    }
    return out;
}

}  // namespace

CutPolyhedron cut_polyhedron_of(const Polyhedron& p, std::size_t first_label) {
    CutPolyhedron c;
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
        CutFace face;
        face.plane = first_label + f;
        for (std::size_t i : p.faces[f]) face.corners_m.push_back(p.vertices_m[i]);
        c.faces.push_back(std::move(face));
    }
    return c;
}

HalfSpaceCut cut_by_plane(const CutPolyhedron& p, const Plane3d& plane, std::size_t plane_label, double tolerance_m) {
    bool any_below = false, any_above = false;
    double deepest_below_m = 0.0, highest_above_m = 0.0;
    std::vector<std::vector<int>> sides(p.faces.size());
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
        for (Vec3 c : p.faces[f].corners_m) {
            const double d = dot(plane.normal, c) - plane.offset_m;
            sides[f].push_back(side_of(d, tolerance_m));
            any_below = any_below || sides[f].back() < 0;
            any_above = any_above || sides[f].back() > 0;
            deepest_below_m = std::min(deepest_below_m, d);
            highest_above_m = std::max(highest_above_m, d);
        }
    }
    if (!any_above) return {p, std::nullopt};
    if (!any_below) return {std::nullopt, p};

    CutPolyhedron below, above;
    std::vector<Vec3> section;  // the points on the plane: vertices on it and crossings
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
        const CutFace& face = p.faces[f];
        for (std::size_t i = 0; i < face.corners_m.size(); ++i) {
            const std::size_t j = (i + 1) % face.corners_m.size();
            if (sides[f][i] == 0) add_distinct(section, face.corners_m[i], tolerance_m);
            if (sides[f][i] * sides[f][j] == -1)
                add_distinct(section, crossing(face.corners_m[i], face.corners_m[j], plane), tolerance_m);
        }
        std::vector<Vec3> low = clip_face(face.corners_m, sides[f], -1, plane);
        std::vector<Vec3> high = clip_face(face.corners_m, sides[f], 1, plane);
        if (low.size() >= 3) below.faces.push_back({std::move(low), face.plane});
        if (high.size() >= 3) above.faces.push_back({std::move(high), face.plane});
    }
    std::vector<Vec3> cap_below = cap_corners(section, plane.normal, tolerance_m);
    if (cap_below.size() < 3) {
        // Vertices within a hair of both sides and no section with an area (round-off at a
        // tolerance's edge): no cut; the piece goes whole to the side it reaches farther into.
        if (highest_above_m > -deepest_below_m) return {std::nullopt, p};
        return {p, std::nullopt};
    }
    std::vector<Vec3> cap_above(cap_below.rbegin(), cap_below.rend());
    below.faces.push_back({std::move(cap_below), plane_label});
    above.faces.push_back({std::move(cap_above), plane_label});
    return {std::move(below), std::move(above)};
}

double cut_polyhedron_volume(const CutPolyhedron& p) {
    if (p.faces.empty()) return 0.0;
    const Vec3 origin = p.faces.front().corners_m.front();  // near the body, for precision
    double six_volume = 0.0;
    for (const CutFace& f : p.faces)
        for (std::size_t i = 1; i + 1 < f.corners_m.size(); ++i)
            six_volume += dot(f.corners_m[0] - origin, cross(f.corners_m[i] - origin, f.corners_m[i + 1] - origin));
    return six_volume / 6.0;
}

std::vector<Vec3> cut_polyhedron_vertices(const CutPolyhedron& p, double tolerance_m) {
    std::vector<Vec3> vertices;
    for (const CutFace& f : p.faces)
        for (Vec3 c : f.corners_m) add_distinct(vertices, c, tolerance_m);
    return vertices;
}

CutIntoBlocks cut_into_blocks(const CutPolyhedron& region, const std::vector<Plane3d>& planes, std::size_t first_label,
                              double min_volume_m3, double tolerance_m) {
    CutIntoBlocks result;
    result.blocks.push_back(region);
    for (std::size_t i = 0; i < planes.size(); ++i) {
        std::vector<CutPolyhedron> next;
        for (CutPolyhedron& block : result.blocks) {
            HalfSpaceCut cut = cut_by_plane(block, planes[i], first_label + i, tolerance_m);
            if (!cut.below || !cut.above) {
                next.push_back(std::move(block));
            } else if (std::min(cut_polyhedron_volume(*cut.below), cut_polyhedron_volume(*cut.above)) < min_volume_m3) {
                ++result.slivers_merged;
                next.push_back(std::move(block));
            } else {
                next.push_back(std::move(*cut.below));
                next.push_back(std::move(*cut.above));
            }
        }
        result.blocks = std::move(next);
    }
    return result;
}

}  // namespace blockdem
