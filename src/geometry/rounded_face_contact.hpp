#pragma once
// The rounded narrow phase's usual step (rounded_contact.hpp): a lasting face contact, whose
// reference edge the axis cache shows the full test would choose again, and its face contact.
// Inline: the step's contact pass (contact/narrow_phase_pair.hpp) runs it in its own body of code
// and calls out (collide_rounded_full, rounded_contact.cpp) only for the full test; collide_rounded
// is made of the same code, so both give the same bits. Not for other callers:
// rounded_contact.hpp is the interface.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "geometry/edge_clipping.hpp"
#include "geometry/polygon_contact.hpp"
#include "geometry/rounded_contact.hpp"

namespace blockdem::rounded_detail {

using edge_clipping::ClipPoint;
using edge_clipping::clip_segment;
using edge_clipping::incident_edge;
using edge_clipping::IncidentEdge;
using edge_clipping::next_corner;
inline std::uint32_t previous_corner(std::uint32_t i, std::uint32_t count) { return i == 0 ? count - 1 : i - 1; }

// How far corner i of the core lies inside corner i of the polygon (rounded_corner_offset):
// the polygon's own when it has them (the body geometry made them this step, from the same
// normals: the same bits), else made here.
[[gnu::always_inline]] inline Vec2 corner_offset(const PolygonView& p, std::uint32_t i, double r) {
    if (p.corner_offsets_m != nullptr) return p.corner_offsets_m[i];
    return rounded_corner_offset(p.normals[previous_corner(i, p.count)], p.normals[i], r);
}

// The separation of the cores along edge i's normal n, measured at corner j of the other
// polygon: (n . v_j - n . v_i) + (r - n . o_j). Grouped so that drawn faces exactly touching
// (first bracket 0, as the sharp model sees them) give exactly 2r, so that the rounded bodies
// touch without a contact, as sharp ones do; computing it from the core corners instead would
// leave an overlap of a few ulps, and such pairs would cost a contact every step.
[[gnu::always_inline]] inline double corner_separation(const PolygonView& poly, std::uint32_t i, const PolygonView& other,
                                                       std::uint32_t j, Vec2 other_offset_j, double r) {
    const Vec2 n = poly.normals[i];
    return (dot(n, other.vertices[j]) - dot(n, poly.vertices[i])) + (r - dot(n, other_offset_j));
}

// How much less a reference edge may separate the cores than the best edge and still be kept
// [m]: the sharp model's 2% of the penetration once the cores overlap, and a round-off margin
// while they are apart (the normal is exact either way then: this only decides between parallel
// faces). It never grows with the best separation, which the cache's test below relies on.
inline double reference_tolerance(double best_separation_m, double r) { return 0.02 * std::max(0.0, -best_separation_m) + 1e-9 * r; }

struct Reference {
    std::uint32_t owner = 0;
    std::uint32_t edge = 0;
    double separation_m = -std::numeric_limits<double>::infinity();  ///< [m]
};

// What a face contact needs of the four corners of the reference edge (r1, r2) and the incident
// edge (i1, i2): their offsets, and the incident corners' separations from the reference edge.
struct FaceCorners {
    std::uint32_t r1, r2, i1, i2;
    Vec2 offset_r1, offset_r2, offset_i1, offset_i2;
    double separation_i1, separation_i2;  ///< [m]
};

[[gnu::always_inline]] inline FaceCorners face_corners(const PolygonView& ref, std::uint32_t edge, const PolygonView& inc,
                                                       std::uint32_t incident, double r) {
    FaceCorners c;
    c.r1 = edge;
    c.r2 = next_corner(edge, ref.count);
    c.i1 = incident;
    c.i2 = next_corner(incident, inc.count);
    c.offset_r1 = corner_offset(ref, c.r1, r);
    c.offset_r2 = corner_offset(ref, c.r2, r);
    c.offset_i1 = corner_offset(inc, c.i1, r);
    c.offset_i2 = corner_offset(inc, c.i2, r);
    c.separation_i1 = corner_separation(ref, edge, inc, c.i1, c.offset_i1, r);
    c.separation_i2 = corner_separation(ref, edge, inc, c.i2, c.offset_i2, r);
    return c;
}

// The face contact on reference edge `edge` of `owner`'s core, incident edge i1 of the other's:
// false when the incident edge lies outside the reference edge's extent, or (separated cores
// only) when the deepest part of the incident core lies outside it, so that the closest points
// are not on this edge. a, b: the drawn polygons (the four core corners it needs are made here).
[[gnu::always_inline]] inline bool face_contact(const PolygonView& a, const PolygonView& b, double r, const Reference& chosen,
                                               const FaceCorners& fc, ContactManifold& m, double gap_m) {
    const PolygonView& ref = chosen.owner == 0 ? a : b;
    const PolygonView& inc = chosen.owner == 0 ? b : a;
    const std::uint32_t inc_owner = 1u - chosen.owner;
    const Vec2 n = ref.normals[chosen.edge];
    const Vec2 v1 = ref.vertices[fc.r1] - fc.offset_r1;
    const Vec2 v2 = ref.vertices[fc.r2] - fc.offset_r2;
    const Vec2 tangent = perp(n);
    const ClipPoint segment[2] = {{inc.vertices[fc.i1] - fc.offset_i1, make_feature(inc_owner, fc.i1)},
                                  {inc.vertices[fc.i2] - fc.offset_i2, make_feature(inc_owner, fc.i2)}};
    ClipPoint once[2];
    ClipPoint twice[2];
    if (clip_segment(segment, once, -tangent, -dot(tangent, v1), make_feature(chosen.owner, fc.r1)) < 2) return false;
    if (clip_segment(once, twice, tangent, dot(tangent, v2), make_feature(chosen.owner, fc.r2)) < 2) return false;
    // Each clipped point's separation: a corner's is the exact one (corner_separation); a cut
    // point's is measured from the core edge's line.
    double separation[2];
    for (int k = 0; k < 2; ++k) {
        const std::uint32_t f = twice[k].feature;
        separation[k] = f == make_feature(inc_owner, fc.i1)   ? fc.separation_i1
                        : f == make_feature(inc_owner, fc.i2) ? fc.separation_i2
                                                              : dot(n, twice[k].p - v1);
    }
    // The clipped part reaches as deep as the whole core: the closest points are on this edge.
    // (Round-off: a cut point of an edge parallel to the reference is computed, not a corner.)
    if (chosen.separation_m >= 0.0 && std::min(separation[0], separation[1]) > chosen.separation_m + 1e-9 * r)
        return false;
    m.normal = chosen.owner == 0 ? n : -n;
    m.reference = make_feature(chosen.owner, chosen.edge);
    m.count = 0;
    for (int k = 0; k < 2; ++k) {
        const double overlap = 2.0 * r - separation[k];
        if (overlap <= -gap_m) continue;  // (a bonded joint's points are kept open up to its gap)
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
        const Vec2 along_incident = segment[1].p - segment[0].p;
        const double shorter_squared = std::min(dot(along_reference, along_reference), dot(along_incident, along_incident));
        const Vec2 span = m.points[1].point_m - m.points[0].point_m;
        const double span_squared = dot(span, span);
        if (span_squared < 1e-4 * shorter_squared)
            m.stiffness_scale = 0.5 + 0.5 * std::sqrt(span_squared) / (0.01 * std::sqrt(shorter_squared));
    }
    return m.count > 0;
}

// The reference edge kept from last step without the full test, when the cache shows that the
// full test would choose it again (as polygon_contact.cpp's AxisCache, on the cores): its
// separation is at least every other edge's, which is at most the incident edge's (bounded by
// its separation at the reference edge's two corners) or the others' at the last full test
// moved by the drift since. Returns nullopt when the full test is needed; owner 2: the
// reference edge now keeps the cores 2r apart.
[[gnu::always_inline]] inline std::optional<Reference> cached_reference(const PolygonView& a, const PolygonView& b, double r,
                                                                         std::uint32_t previous_reference, const AxisCache& cache,
                                                                         FaceCorners& fc, double gap_m) {
    if (previous_reference == no_reference || !(cache.others_max_separation_m < INFINITY)) return std::nullopt;
    const Reference kept{feature_owner(previous_reference), feature_vertex(previous_reference)};
    const PolygonView& ref = kept.owner == 0 ? a : b;
    const PolygonView& inc = kept.owner == 0 ? b : a;
    if (kept.edge >= ref.count) return std::nullopt;
    std::uint32_t i1 = feature_vertex(cache.incident);
    if (!(2.0 * cache.turn_rad + 1e-12 < cache.incident_margin)) {
        i1 = incident_edge(inc, ref.normals[kept.edge]).edge;
        if (make_feature(1u - kept.owner, i1) != cache.incident) return std::nullopt;
    }
    // The deepest corner of the incident core along n is an end of the incident edge (the edge
    // whose normal is nearest -n has the support corner at one end).
    fc = face_corners(ref, kept.edge, inc, i1, r);
    const double separation = std::min(fc.separation_i1, fc.separation_i2);
    if (separation >= 2.0 * r + gap_m) return Reference{2, 0, separation};
    const double incident_at_most = std::min(corner_separation(inc, i1, ref, fc.r1, fc.offset_r1, r),
                                             corner_separation(inc, i1, ref, fc.r2, fc.offset_r2, r));
    const double bound = std::max(incident_at_most, cache.others_max_separation_m + cache.drift_m);
    // Every edge the full test would weigh separates by at most bound, and the tolerance only
    // grows as the best falls: meeting it against bound is enough for the full test to keep it.
    if (separation >= bound - reference_tolerance(bound, r)) return Reference{kept.owner, kept.edge, separation};
    return std::nullopt;
}

/// collide_rounded after its usual step: the full separating-axis test and what follows it
/// (rounded_contact.cpp). Called only by collide_rounded_lasting.
bool collide_rounded_full(const PolygonView& a, const PolygonView& b, double r, std::uint32_t previous_reference,
                          ContactManifold& manifold, AxisCache& cache, double gap_m, const std::uint8_t* seam_a,
                          const std::uint8_t* seam_b);

/// collide_rounded (rounded_contact.hpp): its usual step here, the rest out of line.
[[gnu::always_inline]] inline bool collide_rounded_lasting(const PolygonView& a, const PolygonView& b, double rounding_m,
                                                           std::uint32_t previous_reference, ContactManifold& manifold,
                                                           AxisCache& cache, double gap_m, const std::uint8_t* seam_a,
                                                           const std::uint8_t* seam_b) {
    const double r = rounding_m;
    manifold.count = 0;
    FaceCorners fc{};
    std::optional<Reference> chosen = cached_reference(a, b, r, previous_reference, cache, fc, gap_m);
    if (chosen && chosen->owner == 2) {
        cache = AxisCache{};
        cache.separating = previous_reference;
        return false;
    }
    if (chosen) {
        if (face_contact(a, b, r, *chosen, fc, manifold, gap_m)) return true;
        manifold.count = 0;  // the closest points left the reference edge: the full test decides
    }
    return collide_rounded_full(a, b, r, previous_reference, manifold, cache, gap_m, seam_a, seam_b);
}

}  // namespace blockdem::rounded_detail
