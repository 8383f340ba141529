#include "geometry/rounded_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace blockdem {
namespace {

std::uint32_t next_corner(std::uint32_t i, std::uint32_t count) { return i + 1 == count ? 0 : i + 1; }
std::uint32_t previous_corner(std::uint32_t i, std::uint32_t count) { return i == 0 ? count - 1 : i - 1; }

// Corner i of the core: on the lines of edges i-1 and i, each moved inward by r. (From
// n . (q - v) = -r for both normals: q = v - r (n_{i-1} + n_i) / (1 + n_{i-1} . n_i).)
Vec2 core_corner(Vec2 corner, Vec2 normal_before, Vec2 normal_after, double r) {
    return corner - (r / (1.0 + dot(normal_before, normal_after))) * (normal_before + normal_after);
}

// A core's corners: on the stack for the usual polygons, on the heap for many-sided ones.
class CoreCorners {
public:
    CoreCorners(const PolygonView& p, double r) {
        Vec2* out = p.count <= small_count ? small_ : (large_.resize(p.count), large_.data());
        for (std::uint32_t i = 0; i < p.count; ++i)
            out[i] = core_corner(p.vertices[i], p.normals[previous_corner(i, p.count)], p.normals[i], r);
        view_ = {out, p.normals, p.count};
    }
    CoreCorners(const CoreCorners&) = delete;
    CoreCorners& operator=(const CoreCorners&) = delete;
    const PolygonView& view() const { return view_; }

private:
    static constexpr std::uint32_t small_count = 16;
    Vec2 small_[small_count];
    std::vector<Vec2> large_;
    PolygonView view_;
};

// Separation of other from edge i of poly, and the corner of other that is deepest.
struct EdgeSeparation {
    double separation_m;    ///< [m]
    std::uint32_t deepest;  ///< corner of other
};

EdgeSeparation edge_separation(const PolygonView& poly, std::uint32_t i, const PolygonView& other) {
    const Vec2 n = poly.normals[i];
    EdgeSeparation s{dot(n, other.vertices[0]), 0};
    for (std::uint32_t j = 1; j < other.count; ++j) {
        const double d = dot(n, other.vertices[j]);
        if (d < s.separation_m) s = {d, j};
    }
    s.separation_m -= dot(n, poly.vertices[i]);
    return s;
}

struct Reference {
    std::uint32_t owner = 0;
    std::uint32_t edge = 0;
    double separation_m = -std::numeric_limits<double>::infinity();  ///< [m]
};

// The edge of either core with the largest separation, or nullopt (and separating set) when
// one separates the cores by 2r or more. Last step's edge is kept while it is within a
// tolerance of the best: a small one for separated cores, whose normal is then exact either
// way (it only decides between parallel faces), the sharp model's when the cores overlap.
std::optional<Reference> choose_reference(const PolygonView& a, const PolygonView& b, double r,
                                          std::uint32_t previous_reference, std::uint32_t& separating) {
    Reference best;
    double previous_separation = -std::numeric_limits<double>::infinity();
    for (std::uint32_t owner = 0; owner < 2; ++owner) {
        const PolygonView& poly = owner == 0 ? a : b;
        const PolygonView& other = owner == 0 ? b : a;
        for (std::uint32_t i = 0; i < poly.count; ++i) {
            const double s = edge_separation(poly, i, other).separation_m;
            if (s >= 2.0 * r) {
                separating = make_feature(owner, i);
                return std::nullopt;
            }
            if (s > best.separation_m) best = {owner, i, s};
            if (make_feature(owner, i) == previous_reference) previous_separation = s;
        }
    }
    const double tolerance = best.separation_m < 0.0 ? 0.02 * -best.separation_m + 1e-15 : 1e-9 * r;
    if (previous_reference != no_reference && previous_separation >= best.separation_m - tolerance)
        return Reference{feature_owner(previous_reference), feature_vertex(previous_reference), previous_separation};
    return best;
}

// The edge of incident whose outward normal points most against n.
std::uint32_t incident_edge(const PolygonView& incident, Vec2 n) {
    std::uint32_t best = 0;
    double most_against = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = 0; i < incident.count; ++i) {
        const double d = dot(incident.normals[i], n);
        if (d < most_against) {
            most_against = d;
            best = i;
        }
    }
    return best;
}

struct ClipPoint {
    Vec2 p;
    std::uint32_t feature;
};

// Keeps the part of segment (in[0], in[1]) where dot(direction, x) <= offset; a point made by
// the cut takes the feature id cut.
int clip_segment(const ClipPoint in[2], ClipPoint out[2], Vec2 direction, double offset, std::uint32_t cut) {
    int n = 0;
    const double d0 = dot(direction, in[0].p) - offset;
    const double d1 = dot(direction, in[1].p) - offset;
    if (d0 <= 0.0) out[n++] = in[0];
    if (d1 <= 0.0) out[n++] = in[1];
    if (d0 * d1 < 0.0) {
        const double f = d0 / (d0 - d1);
        out[n++] = {in[0].p + f * (in[1].p - in[0].p), cut};
    }
    return n;
}

// The face contact on reference edge `edge` of `owner`'s core: false when the incident edge lies
// outside the reference edge's extent, or (separated cores only) when the deepest part of the
// incident core lies outside it, so that the closest points are not on this edge.
bool face_contact(const PolygonView& a, const PolygonView& b, double r, const Reference& chosen, ContactManifold& m) {
    const PolygonView& ref = chosen.owner == 0 ? a : b;
    const PolygonView& inc = chosen.owner == 0 ? b : a;
    const std::uint32_t inc_owner = 1u - chosen.owner;
    const std::uint32_t r1 = chosen.edge;
    const std::uint32_t r2 = next_corner(r1, ref.count);
    const Vec2 n = ref.normals[r1];
    const Vec2 v1 = ref.vertices[r1];
    const Vec2 v2 = ref.vertices[r2];
    const Vec2 tangent = perp(n);
    const std::uint32_t i1 = incident_edge(inc, n);
    const std::uint32_t i2 = next_corner(i1, inc.count);
    const ClipPoint segment[2] = {{inc.vertices[i1], make_feature(inc_owner, i1)},
                                  {inc.vertices[i2], make_feature(inc_owner, i2)}};
    ClipPoint once[2];
    ClipPoint twice[2];
    if (clip_segment(segment, once, -tangent, -dot(tangent, v1), make_feature(chosen.owner, r1)) < 2) return false;
    if (clip_segment(once, twice, tangent, dot(tangent, v2), make_feature(chosen.owner, r2)) < 2) return false;
    const double separation[2] = {dot(n, twice[0].p - v1), dot(n, twice[1].p - v1)};
    // The clipped part reaches as deep as the whole core: the closest points are on this edge.
    // (Round-off: a cut point of an edge parallel to the reference is computed, not a corner.)
    if (chosen.separation_m >= 0.0 && std::min(separation[0], separation[1]) > chosen.separation_m + 1e-9 * r)
        return false;
    m.normal = chosen.owner == 0 ? n : -n;
    m.reference = make_feature(chosen.owner, r1);
    m.count = 0;
    for (int k = 0; k < 2; ++k) {
        const double overlap = 2.0 * r - separation[k];
        if (overlap <= 0.0) continue;
        ContactGeometry& g = m.points[m.count++];
        g.point_m = twice[k].p - (r - 0.5 * overlap) * n;  // midway between the two rounded surfaces
        g.overlap_m = overlap;
        g.feature = twice[k].feature;
    }
    m.stiffness_scale = 1.0;
    if (m.count == 2) {
        // Two points closing up become the one corner point that follows (see the header): the
        // pair's stiffness falls from two points' to one's as the span falls below 1% of the
        // shorter edge.
        const Vec2 along_reference = v2 - v1;
        const Vec2 along_incident = inc.vertices[i2] - inc.vertices[i1];
        const double shorter_squared = std::min(dot(along_reference, along_reference), dot(along_incident, along_incident));
        const Vec2 span = m.points[1].point_m - m.points[0].point_m;
        const double span_squared = dot(span, span);
        if (span_squared < 1e-4 * shorter_squared)
            m.stiffness_scale = 0.5 + 0.5 * std::sqrt(span_squared) / (0.01 * std::sqrt(shorter_squared));
    }
    return m.count > 0;
}

// The point of segment (p, q) closest to x.
Vec2 closest_on_segment(Vec2 x, Vec2 p, Vec2 q) {
    const Vec2 d = q - p;
    const double dd = dot(d, d);
    const double f = dd > 0.0 ? std::clamp(dot(x - p, d) / dd, 0.0, 1.0) : 0.0;
    return p + f * d;
}

struct ClosestPoints {
    double distance_m = std::numeric_limits<double>::infinity();  ///< [m]
    Vec2 on_a;
    Vec2 on_b;
    std::uint32_t feature = 0;  ///< the corner in the pair
};

// The closest points of separated cores a and b when they are not on one face: a corner of one
// against an edge (or corner) of the other. Only corners within 2r of the other core along the
// separating direction u (from a to b) can be closest, and only edges with such a corner at one
// end. Corners of the incident core (owner incident_owner) are tried first, so that a
// corner-to-corner pair is named by the incident corner as in the face contact it follows.
ClosestPoints closest_corner_points(const PolygonView& a, const PolygonView& b, Vec2 u, double r,
                                    std::uint32_t incident_owner) {
    double a_most = -std::numeric_limits<double>::infinity();
    double b_least = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = 0; i < a.count; ++i) a_most = std::max(a_most, dot(u, a.vertices[i]));
    for (std::uint32_t j = 0; j < b.count; ++j) b_least = std::min(b_least, dot(u, b.vertices[j]));
    auto near_a = [&](std::uint32_t i) { return dot(u, a.vertices[i]) > b_least - 2.0 * r; };
    auto near_b = [&](std::uint32_t j) { return dot(u, b.vertices[j]) < a_most + 2.0 * r; };
    ClosestPoints best;
    for (std::uint32_t pass = 0; pass < 2; ++pass) {
        const std::uint32_t owner = pass == 0 ? incident_owner : 1u - incident_owner;
        const PolygonView& corners = owner == 0 ? a : b;
        const PolygonView& edges = owner == 0 ? b : a;
        for (std::uint32_t i = 0; i < corners.count; ++i) {
            if (!(owner == 0 ? near_a(i) : near_b(i))) continue;
            for (std::uint32_t e = 0; e < edges.count; ++e) {
                const std::uint32_t f = next_corner(e, edges.count);
                if (!(owner == 0 ? near_b(e) || near_b(f) : near_a(e) || near_a(f))) continue;
                const Vec2 x = corners.vertices[i];
                const Vec2 y = closest_on_segment(x, edges.vertices[e], edges.vertices[f]);
                const double d = length(y - x);
                if (d < best.distance_m)
                    best = owner == 0 ? ClosestPoints{d, x, y, make_feature(0, i)} : ClosestPoints{d, y, x, make_feature(1, i)};
            }
        }
    }
    return best;
}

}  // namespace

std::optional<std::string> rounding_problem(const std::vector<Vec2>& vertices, const std::vector<Vec2>& normals,
                                            double least_width_m, double rounding_m) {
    if (rounding_m <= 0.0) return std::nullopt;
    if (rounding_m >= rounding_width_fraction * least_width_m)
        return fmt::format("[contact] rounding = {:g} m must be below {:g} of the body's least width ({:g} m), i.e. "
                           "below {:g} m",
                           rounding_m, rounding_width_fraction, least_width_m, rounding_width_fraction * least_width_m);
    const std::uint32_t count = static_cast<std::uint32_t>(vertices.size());
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t j = next_corner(i, count);
        const Vec2 from = core_corner(vertices[i], normals[previous_corner(i, count)], normals[i], rounding_m);
        const Vec2 to = core_corner(vertices[j], normals[i], normals[j], rounding_m);
        // The core's edge must keep the drawn edge's direction (else the corners' arcs overlap).
        if (dot(to - from, vertices[j] - vertices[i]) <= 0.0)
            return fmt::format("[contact] rounding = {:g} m removes edge {} (corner {} to {}, {:g} m long) of the body: "
                               "its corners are too sharp or the edge too short for arcs of that radius",
                               rounding_m, i, i, j, length(vertices[j] - vertices[i]));
    }
    return std::nullopt;
}

bool collide_rounded(const PolygonView& a, const PolygonView& b, double rounding_m, std::uint32_t previous_reference,
                     ContactManifold& manifold, AxisCache& cache) {
    manifold.count = 0;
    cache = AxisCache{};
    const CoreCorners core_a(a, rounding_m);
    const CoreCorners core_b(b, rounding_m);
    const PolygonView& ca = core_a.view();
    const PolygonView& cb = core_b.view();
    std::uint32_t separating = no_reference;
    const std::optional<Reference> chosen = choose_reference(ca, cb, rounding_m, previous_reference, separating);
    if (!chosen) {
        cache.separating = separating;
        return false;
    }
    if (face_contact(ca, cb, rounding_m, *chosen, manifold)) return true;
    manifold.count = 0;
    if (chosen->separation_m < 0.0) return false;  // overlapping cores, incident edge beside the reference (as sharp)
    const Vec2 n = (chosen->owner == 0 ? ca : cb).normals[chosen->edge];
    const Vec2 u = chosen->owner == 0 ? n : -n;
    const ClosestPoints c = closest_corner_points(ca, cb, u, rounding_m, 1u - chosen->owner);
    const double overlap = 2.0 * rounding_m - c.distance_m;
    if (!(overlap > 0.0)) return false;
    // Cores touching (distance 0) leave the line between them undefined: the reference normal.
    manifold.normal = c.distance_m > 1e-12 * rounding_m ? (1.0 / c.distance_m) * (c.on_b - c.on_a) : u;
    manifold.reference = make_feature(chosen->owner, chosen->edge);
    manifold.count = 1;
    manifold.points[0].point_m = 0.5 * (c.on_a + c.on_b);
    manifold.points[0].overlap_m = overlap;
    manifold.points[0].feature = c.feature;
    manifold.stiffness_scale = 1.0;
    return true;
}

}  // namespace blockdem
