// Convex polyhedra: the hull by supporting planes, the checks that name a user's mistake, and the
// volume integrals (the divergence theorem over tetrahedra; see Mirtich 1996, "Fast and accurate
// computation of polyhedral mass properties", for the same sums taken over faces).
#include "geometry/polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace blockdem {
namespace {

// Distances below this fraction of the body's size count as zero: far above round-off
// (1e-16) for any body a user draws, far below any feature a user means.
constexpr double relative_tolerance = 1e-9;

std::string point_text(Vec3 p) { return fmt::format("({:g}, {:g}, {:g})", p.x, p.y, p.z); }

Vec3 mean_vertex(const std::vector<Vec3>& v) {
    Vec3 sum;
    for (Vec3 p : v) sum += p;
    return (1.0 / static_cast<double>(v.size())) * sum;
}

// The largest distance from the mean vertex [m]: the scale of the tolerances.
double size_of(const std::vector<Vec3>& v) {
    const Vec3 mean = mean_vertex(v);
    double size = 0.0;
    for (Vec3 p : v) size = std::max(size, length(p - mean));
    return size;
}

// The corners of a face's points, counter-clockwise about the outward normal n: the 2-D hull
// (Andrew's monotone chain) in a basis (u, v) of the face's plane with u x v = n. Points on the
// polygon's edges are not corners (strict turns only).
std::vector<std::size_t> face_corners(const std::vector<Vec3>& vertices, const std::vector<std::size_t>& on_plane,
                                      Vec3 n, double area_tolerance_m2) {
    const Vec3 u = normalized(vertices[on_plane[1]] - vertices[on_plane[0]]);
    const Vec3 v = cross(n, u);
    struct Planar {
        Vec2 p;
        std::size_t index;
    };
    std::vector<Planar> points;
    for (std::size_t i : on_plane) {
        const Vec3 d = vertices[i] - vertices[on_plane[0]];
        points.push_back({{dot(d, u), dot(d, v)}, i});
    }
    std::sort(points.begin(), points.end(),
              [](const Planar& a, const Planar& b) { return a.p.x < b.p.x || (a.p.x == b.p.x && a.p.y < b.p.y); });
    std::vector<Planar> hull(2 * points.size());
    std::size_t k = 0;
    const auto turns_left = [&](const Planar& o, const Planar& a, const Planar& b) {
        return cross(a.p - o.p, b.p - o.p) > area_tolerance_m2;
    };
    for (std::size_t i = 0; i < points.size(); ++i) {  // lower chain
        while (k >= 2 && !turns_left(hull[k - 2], hull[k - 1], points[i])) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
        while (k >= lower && !turns_left(hull[k - 2], hull[k - 1], points[i])) --k;
        hull[k++] = points[i];
    }
    std::vector<std::size_t> corners;
    for (std::size_t i = 0; i + 1 < k; ++i) corners.push_back(hull[i].index);  // the last repeats the first
    return corners;
}

// Newell's normal of a listed polygon: its area vector, whatever the order's quality.
Vec3 newell_normal(const std::vector<Vec3>& vertices, const std::vector<std::size_t>& face) {
    Vec3 n;
    for (std::size_t i = 0; i < face.size(); ++i) n += cross(vertices[face[i]], vertices[face[(i + 1) % face.size()]]);
    return n;
}

}  // namespace

Polyhedron convex_polyhedron(const std::vector<Vec3>& vertices) {
    const std::size_t n = vertices.size();
    if (n < 4) throw std::invalid_argument(fmt::format("a polyhedron needs at least 4 vertices, this one has {}", n));
    const double size = size_of(vertices);
    const double tolerance_m = relative_tolerance * size;
    const double area_tolerance_m2 = relative_tolerance * size * size;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (length(vertices[i] - vertices[j]) <= tolerance_m)
                throw std::invalid_argument(
                    fmt::format("vertices {} and {} coincide at {}", i, j, point_text(vertices[i])));

    Polyhedron hull;
    hull.vertices_m = vertices;
    std::set<std::vector<std::size_t>> seen;  // each face's points, sorted
    std::vector<std::uint8_t> on_surface(n, 0), is_corner(n, 0);
    // The faces found so far that each vertex lies on, and each face's points as flags: three
    // vertices on one found face span that face again, and are skipped (a 32-sided cap would
    // otherwise be found C(32, 3) = 4960 times; measured: a 32-sided prism 7.7 ms -> 2.4 ms, a
    // 64-sided one 119 ms -> 25 ms).
    std::vector<std::vector<std::size_t>> faces_of(n);
    std::vector<std::vector<std::uint8_t>> on_face;
    const auto on_one_found_face = [&](std::size_t i, std::size_t j, std::size_t k) {
        for (std::size_t f : faces_of[i])
            if (on_face[f][j] && on_face[f][k]) return true;
        return false;
    };
    bool has_area = false;
    std::vector<std::size_t> on_plane;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            for (std::size_t k = j + 1; k < n; ++k) {
                if (on_one_found_face(i, j, k)) continue;
                const Vec3 area = cross(vertices[j] - vertices[i], vertices[k] - vertices[i]);
                if (length(area) <= area_tolerance_m2) continue;  // (nearly) collinear
                has_area = true;
                Vec3 normal = normalized(area);
                bool any_above = false, any_below = false;
                for (std::size_t m = 0; m < n && !(any_above && any_below); ++m) {
                    const double d = dot(normal, vertices[m] - vertices[i]);
                    any_above = any_above || d > tolerance_m;
                    any_below = any_below || d < -tolerance_m;
                }
                if (any_above && any_below) continue;  // cuts through: not a supporting plane
                if (!any_above && !any_below)
                    throw std::invalid_argument("all vertices lie in one plane: the polyhedron has no volume");
                if (any_above) normal = -normal;  // outward: every vertex below
                on_plane.clear();
                for (std::size_t m = 0; m < n; ++m)
                    if (std::abs(dot(normal, vertices[m] - vertices[i])) <= tolerance_m) on_plane.push_back(m);
                if (!seen.insert(on_plane).second) continue;
                std::vector<std::size_t> corners = face_corners(vertices, on_plane, normal, area_tolerance_m2);
                on_face.emplace_back(n, 0);
                for (std::size_t m : on_plane) {
                    on_surface[m] = 1;
                    on_face.back()[m] = 1;
                    faces_of[m].push_back(on_face.size() - 1);
                }
                for (std::size_t m : corners) is_corner[m] = 1;
                hull.faces.push_back(std::move(corners));
                hull.face_normals.push_back(normal);
            }
        }
    }
    if (!has_area) throw std::invalid_argument("all vertices lie on one line: the polyhedron has no volume");
    for (std::size_t m = 0; m < n; ++m)
        if (!on_surface[m])
            throw std::invalid_argument(fmt::format(
                "vertex {} {} lies inside the hull of the others: the vertices are not those of a convex polyhedron", m,
                point_text(vertices[m])));
    for (std::size_t m = 0; m < n; ++m)
        if (!is_corner[m])
            throw std::invalid_argument(
                fmt::format("vertex {} {} lies on an edge or inside a face of the hull, not at a corner", m,
                            point_text(vertices[m])));
    // Euler's formula for a closed convex surface: a guard against a tolerance that let a face through twice.
    std::size_t edge_ends = 0;
    for (const auto& f : hull.faces) edge_ends += f.size();
    if (n + hull.faces.size() != edge_ends / 2 + 2)
        throw std::invalid_argument("the hull's faces do not close (V - E + F != 2): vertices too close to tell apart");
    return hull;
}

Polyhedron convex_polyhedron(const std::vector<Vec3>& vertices, const std::vector<std::vector<std::size_t>>& faces) {
    Polyhedron hull = convex_polyhedron(vertices);
    std::map<std::vector<std::size_t>, std::size_t> hull_face_of;  // sorted indices -> hull face
    for (std::size_t f = 0; f < hull.faces.size(); ++f) {
        std::vector<std::size_t> key = hull.faces[f];
        std::sort(key.begin(), key.end());
        hull_face_of[key] = f;
    }
    std::vector<std::uint8_t> listed(hull.faces.size(), 0);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::vector<std::size_t>& face = faces[f];
        for (std::size_t i : face)
            if (i >= vertices.size())
                throw std::invalid_argument(
                    fmt::format("face {} names vertex {}, but there are {} vertices", f, i, vertices.size()));
        std::vector<std::size_t> key = face;
        std::sort(key.begin(), key.end());
        const auto found = hull_face_of.find(key);
        if (found == hull_face_of.end())
            throw std::invalid_argument(fmt::format("face {} is not a face of the convex hull of the vertices", f));
        const std::size_t h = found->second;
        if (listed[h]) throw std::invalid_argument(fmt::format("face {} is listed twice", f));
        listed[h] = 1;
        if (dot(newell_normal(vertices, face), hull.face_normals[h]) < 0.0)
            throw std::invalid_argument(fmt::format(
                "face {} is inverted: its vertices run clockwise seen from outside (they must run counter-clockwise)",
                f));
        // The same cycle as the hull's, from the listed first vertex on.
        const std::vector<std::size_t>& corners = hull.faces[h];
        const std::size_t start =
            static_cast<std::size_t>(std::find(corners.begin(), corners.end(), face[0]) - corners.begin());
        for (std::size_t i = 0; i < face.size(); ++i)
            if (corners[(start + i) % corners.size()] != face[i])
                throw std::invalid_argument(fmt::format("face {} lists its vertices out of order around the face", f));
        hull.faces[h] = face;
    }
    for (std::size_t h = 0; h < hull.faces.size(); ++h)
        if (!listed[h]) {
            std::string corners;
            for (std::size_t i : hull.faces[h]) corners += fmt::format(" {}", i);
            throw std::invalid_argument(fmt::format("the faces leave out the hull's face through vertices{}", corners));
        }
    return hull;
}

PolyhedronProperties polyhedron_properties(const Polyhedron& p) {
    const Vec3 apex = mean_vertex(p.vertices_m);
    double volume = 0.0;
    Vec3 first;       // integral of r dV, r from the apex
    Matrix3d second;  // integral of r r^T dV
    for (const auto& face : p.faces) {
        const Vec3 a = p.vertices_m[face[0]] - apex;
        for (std::size_t k = 1; k + 1 < face.size(); ++k) {
            const Vec3 b = p.vertices_m[face[k]] - apex;
            const Vec3 c = p.vertices_m[face[k + 1]] - apex;
            // Tetrahedron (0, a, b, c): V = a . (b x c) / 6, integral of r = V (a + b + c) / 4,
            // integral of r r^T = V / 20 (a a^T + b b^T + c c^T + s s^T) with s = a + b + c.
            const double v = dot(a, cross(b, c)) / 6.0;
            const Vec3 s = a + b + c;
            volume += v;
            first += (v / 4.0) * s;
            second = second + (v / 20.0) * (Matrix3d::outer(a, a) + Matrix3d::outer(b, b) + Matrix3d::outer(c, c) +
                                            Matrix3d::outer(s, s));
        }
    }
    PolyhedronProperties props;
    props.volume_m3 = volume;
    const Vec3 centroid = (1.0 / volume) * first;
    props.centroid_m = apex + centroid;
    const Matrix3d about_centroid = second - volume * Matrix3d::outer(centroid, centroid);
    props.inertia_m5 = about_centroid.trace() * Matrix3d::identity() - about_centroid;
    return props;
}

PrincipalAxes principal_axes(const Matrix3d& inertia) {
    const SymmetricEigen e = symmetric_eigen(inertia);
    return {e.values, from_rotation_matrix(e.vectors)};
}

std::vector<Vec3> box_vertices(Vec3 lengths_m, Vec3 center_m, Quaternion orientation) {
    std::vector<Vec3> corners;
    for (double sz : {-0.5, 0.5})
        for (double sy : {-0.5, 0.5})
            for (double sx : {-0.5, 0.5})
                corners.push_back(center_m +
                                  rotate(orientation, {sx * lengths_m.x, sy * lengths_m.y, sz * lengths_m.z}));
    return corners;
}

std::vector<Vec3> prism_vertices(const std::vector<Vec2>& polygon_m, double height_m) {
    std::vector<Vec3> corners;
    for (double z : {0.0, height_m})
        for (Vec2 p : polygon_m) corners.push_back({p.x, p.y, z});
    return corners;
}

}  // namespace blockdem
