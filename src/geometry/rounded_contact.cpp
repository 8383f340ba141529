#include "geometry/rounded_contact.hpp"
#include "geometry/edge_clipping.hpp"
#include "geometry/rounded_face_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace blockdem {
namespace {

using namespace rounded_detail;

using edge_clipping::ClipPoint;
using edge_clipping::clip_segment;
using edge_clipping::incident_edge;
using edge_clipping::IncidentEdge;
using edge_clipping::next_corner;



// Room for one vector per corner: on the stack for the usual polygons, on the heap for
// many-sided ones (the narrow phase runs for every pair at every step: no allocation there).
class CornerVectors {
public:
    explicit CornerVectors(std::uint32_t count) : data_(count <= small_count ? small_ : (large_.resize(count), large_.data())) {}
    CornerVectors(const CornerVectors&) = delete;
    CornerVectors& operator=(const CornerVectors&) = delete;
    Vec2& operator[](std::uint32_t i) { return data_[i]; }
    Vec2 operator[](std::uint32_t i) const { return data_[i]; }
    const Vec2* data() const { return data_; }

private:
    static constexpr std::uint32_t small_count = 16;
    Vec2 small_[small_count];
    std::vector<Vec2> large_;
    Vec2* data_;
};

// Every corner offset of a polygon.
class CornerOffsets : public CornerVectors {
public:
    CornerOffsets(const PolygonView& p, double r) : CornerVectors(p.count) {
        for (std::uint32_t i = 0; i < p.count; ++i) (*this)[i] = corner_offset(p, i, r);
    }
};

// Separation of the other core from edge i of poly's core.
double edge_separation(const PolygonView& poly, std::uint32_t i, const PolygonView& other, const CornerOffsets& offsets,
                       double r) {
    double least = corner_separation(poly, i, other, 0, offsets[0], r);
    for (std::uint32_t j = 1; j < other.count; ++j) least = std::min(least, corner_separation(poly, i, other, j, offsets[j], r));
    return least;
}



// The edge of either core with the largest separation, or nullopt (and separating set) when
// one separates the cores by 2r + gap_m or more. Last step's edge is kept while it is within a
// tolerance of the best (reference_tolerance).
std::optional<Reference> choose_reference(const PolygonView& a, const PolygonView& b, const CornerOffsets& offsets_a,
                                          const CornerOffsets& offsets_b, double r, std::uint32_t previous_reference,
                                          std::uint32_t& separating, double gap_m) {
    Reference best;
    double previous_separation = -std::numeric_limits<double>::infinity();
    for (std::uint32_t owner = 0; owner < 2; ++owner) {
        const PolygonView& poly = owner == 0 ? a : b;
        const PolygonView& other = owner == 0 ? b : a;
        for (std::uint32_t i = 0; i < poly.count; ++i) {
            const double s = edge_separation(poly, i, other, owner == 0 ? offsets_b : offsets_a, r);
            if (s >= 2.0 * r + gap_m) {
                separating = make_feature(owner, i);
                return std::nullopt;
            }
            if (s > best.separation_m) best = {owner, i, s};
            if (make_feature(owner, i) == previous_reference) previous_separation = s;
        }
    }
    if (previous_reference != no_reference && previous_separation >= best.separation_m - reference_tolerance(best.separation_m, r))
        return Reference{feature_owner(previous_reference), feature_vertex(previous_reference), previous_separation};
    return best;
}

// The largest separation over every edge of both cores except the two named ones.
double largest_other_separation(const PolygonView& a, const PolygonView& b, const CornerOffsets& offsets_a,
                                const CornerOffsets& offsets_b, double r, std::uint32_t skip1, std::uint32_t skip2) {
    double largest = -std::numeric_limits<double>::infinity();
    for (std::uint32_t owner = 0; owner < 2; ++owner) {
        const PolygonView& poly = owner == 0 ? a : b;
        const PolygonView& other = owner == 0 ? b : a;
        for (std::uint32_t i = 0; i < poly.count; ++i) {
            const std::uint32_t f = make_feature(owner, i);
            if (f != skip1 && f != skip2)
                largest = std::max(largest, edge_separation(poly, i, other, owner == 0 ? offsets_b : offsets_a, r));
        }
    }
    return largest;
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
    bool at_seam = false;       ///< a closest point is a seam corner (rounded_outline.hpp)
};

// Seam flags of the two polygons (nullptr: none).
struct Seams {
    const std::uint8_t* a = nullptr;
    const std::uint8_t* b = nullptr;
    bool any() const { return a != nullptr || b != nullptr; }
};

bool is_seam(const std::uint8_t* seam, std::uint32_t i) { return seam != nullptr && seam[i] != 0; }

// The closest points of separated cores a and b (given as core polygons) when they are not on one face: a corner of one
// against an edge (or corner) of the other. Only corners within 2r of the other core along the
// separating direction u (from a to b) can be closest, and only edges with such a corner at one
// end. Corners of the incident core (owner incident_owner) are tried first, so that a
// corner-to-corner pair is named by the incident corner as in the face contact it follows.
// A closest point at a seam corner of a concave body's part (either the corner, or an edge's end)
// is marked: there the contact belongs to the neighbouring part (rounded_outline.hpp). Of two
// candidates at one distance the one off the seams is kept.
ClosestPoints closest_core_points(const PolygonView& a, const PolygonView& b, Vec2 u, double reach_m,
                                  std::uint32_t incident_owner, Seams seams) {
    double a_most = -std::numeric_limits<double>::infinity();
    double b_least = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = 0; i < a.count; ++i) a_most = std::max(a_most, dot(u, a.vertices[i]));
    for (std::uint32_t j = 0; j < b.count; ++j) b_least = std::min(b_least, dot(u, b.vertices[j]));
    auto near_a = [&](std::uint32_t i) { return dot(u, a.vertices[i]) > b_least - reach_m; };
    auto near_b = [&](std::uint32_t j) { return dot(u, b.vertices[j]) < a_most + reach_m; };
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
                if (d > best.distance_m || (d == best.distance_m && !best.at_seam)) continue;
                bool at_seam = false;
                if (seams.any()) [[unlikely]] {
                    const std::uint8_t* corner_seams = owner == 0 ? seams.a : seams.b;
                    const std::uint8_t* edge_seams = owner == 0 ? seams.b : seams.a;
                    // (An edge's end as closest_on_segment makes it: exact, or within round-off.)
                    const double end_m = 1e-9 * reach_m;
                    at_seam = is_seam(corner_seams, i) || (is_seam(edge_seams, e) && norm_bound(y - edges.vertices[e]) <= end_m) ||
                              (is_seam(edge_seams, f) && norm_bound(y - edges.vertices[f]) <= end_m);
                }
                if (d == best.distance_m && at_seam) continue;
                best = owner == 0 ? ClosestPoints{d, x, y, make_feature(0, i), at_seam}
                                  : ClosestPoints{d, y, x, make_feature(1, i), at_seam};
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
        const Vec2 from = vertices[i] - rounded_corner_offset(normals[previous_corner(i, count)], normals[i], rounding_m);
        const Vec2 to = vertices[j] - rounded_corner_offset(normals[i], normals[j], rounding_m);
        // The core's edge must keep the drawn edge's direction (else the corners' arcs overlap).
        if (dot(to - from, vertices[j] - vertices[i]) <= 0.0)
            return fmt::format("[contact] rounding = {:g} m removes edge {} (corner {} to {}, {:g} m long) of the body: "
                               "its corners are too sharp or the edge too short for arcs of that radius",
                               rounding_m, i, i, j, length(vertices[j] - vertices[i]));
    }
    return std::nullopt;
}

namespace {


// Corner contact: one point between the closest points of the separated cores.
bool corner_contact(const PolygonView& a, const PolygonView& b, const CornerOffsets& offsets_a,
                    const CornerOffsets& offsets_b, double r, const Reference& chosen, ContactManifold& m, double gap_m,
                    Seams seams) {
    CornerVectors corners_a(a.count), corners_b(b.count);
    for (std::uint32_t i = 0; i < a.count; ++i) corners_a[i] = a.vertices[i] - offsets_a[i];
    for (std::uint32_t j = 0; j < b.count; ++j) corners_b[j] = b.vertices[j] - offsets_b[j];
    const PolygonView ca{corners_a.data(), a.normals, a.count};
    const PolygonView cb{corners_b.data(), b.normals, b.count};
    const Vec2 n = (chosen.owner == 0 ? a : b).normals[chosen.edge];
    const Vec2 u = chosen.owner == 0 ? n : -n;
    const ClosestPoints c = closest_core_points(ca, cb, u, 2.0 * r + gap_m, 1u - chosen.owner, seams);
    if (c.at_seam) return false;  // the neighbouring part's contact (rounded_outline.hpp)
    const double overlap = 2.0 * r - c.distance_m;
    if (!(overlap > -gap_m)) return false;
    // Cores touching (distance 0) leave the line between them undefined: the reference normal.
    m.normal = c.distance_m > 1e-12 * r ? (1.0 / c.distance_m) * (c.on_b - c.on_a) : u;
    m.reference = make_feature(chosen.owner, chosen.edge);
    m.count = 1;
    m.points[0].point_m = 0.5 * (c.on_a + c.on_b);
    m.points[0].overlap_m = overlap;
    m.points[0].feature = c.feature;
    m.stiffness_scale = 1.0;
    return true;
}

}  // namespace

namespace rounded_detail {

bool collide_rounded_full(const PolygonView& a, const PolygonView& b, double r, std::uint32_t previous_reference,
                          ContactManifold& manifold, AxisCache& cache, double gap_m, const std::uint8_t* seam_a,
                          const std::uint8_t* seam_b) {
    cache = AxisCache{};
    const CornerOffsets offsets_a(a, r);
    const CornerOffsets offsets_b(b, r);
    std::uint32_t separating = no_reference;
    const std::optional<Reference> chosen = choose_reference(a, b, offsets_a, offsets_b, r, previous_reference, separating, gap_m);
    if (!chosen) {
        cache.separating = separating;
        return false;
    }
    const PolygonView& ref = chosen->owner == 0 ? a : b;
    const PolygonView& inc = chosen->owner == 0 ? b : a;
    const IncidentEdge incident = incident_edge(inc, ref.normals[chosen->edge]);
    if (face_contact(a, b, r, *chosen, face_corners(ref, chosen->edge, inc, incident.edge, r), manifold, gap_m)) {
        cache.incident = make_feature(1u - chosen->owner, incident.edge);
        cache.incident_margin = incident.margin;
        cache.others_max_separation_m = largest_other_separation(a, b, offsets_a, offsets_b, r,
                                                                 make_feature(chosen->owner, chosen->edge), cache.incident);
        return true;
    }
    manifold.count = 0;
    if (chosen->separation_m < 0.0) return false;  // overlapping cores, incident edge beside the reference (as sharp)
    return corner_contact(a, b, offsets_a, offsets_b, r, *chosen, manifold, gap_m, Seams{seam_a, seam_b});
}

}  // namespace rounded_detail

bool collide_rounded(const PolygonView& a, const PolygonView& b, double rounding_m, std::uint32_t previous_reference,
                     ContactManifold& manifold, AxisCache& cache, double gap_m, const std::uint8_t* seam_a,
                     const std::uint8_t* seam_b) {
    return rounded_detail::collide_rounded_lasting(a, b, rounding_m, previous_reference, manifold, cache, gap_m, seam_a, seam_b);
}

}  // namespace blockdem
