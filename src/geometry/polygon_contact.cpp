#include "geometry/polygon_contact.hpp"
#include "geometry/edge_clipping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace blockdem {
namespace {

using edge_clipping::ClipPoint;
using edge_clipping::clip_segment;
using edge_clipping::incident_edge;
using edge_clipping::IncidentEdge;
using edge_clipping::next_corner;

struct Axis {
    double separation_m = -std::numeric_limits<double>::infinity();  ///< [m] < 0 when penetrating
    std::uint32_t edge = 0;
};

// Separation of polygon other from edge i of poly: the least signed distance of other's corners
// to the edge's line (negative: the deepest corner is inside by that much).
// (The edge's offset dot(n, p) is taken out of the loop: this is the hottest loop of a step.)
[[gnu::always_inline]] inline double edge_separation(const PolygonView& poly, std::uint32_t i, const PolygonView& other) {
    const Vec2 n = poly.normals[i];
    const Vec2* v = other.vertices;
    double least = dot(n, v[0]);
    if (other.count == 4) {
        // Quadrilaterals (bricks, most blocks) unrolled: no loop, two independent minima.
        least = std::min(std::min(least, dot(n, v[1])), std::min(dot(n, v[2]), dot(n, v[3])));
    } else {
        for (std::uint32_t j = 1; j < other.count; ++j) least = std::min(least, dot(n, v[j]));
    }
    return least - dot(n, poly.vertices[i]);
}

// The edge of poly that other penetrates least. Stops early once a separating edge is found
// (separation >= gap_m; with gap 0, polygons that only touch have no point with a positive
// overlap either).
Axis best_axis(const PolygonView& poly, const PolygonView& other, double gap_m) {
    Axis best;
    for (std::uint32_t i = 0; i < poly.count; ++i) {
        const double s = edge_separation(poly, i, other);
        if (s > best.separation_m) best = {s, i};
        if (s >= gap_m) break;
    }
    return best;
}

// How much more a reference edge may penetrate than the best edge and still be kept [m].
double reference_tolerance(double best_separation_m) { return 0.02 * std::abs(best_separation_m) + 1e-15; }

struct Reference {
    std::uint32_t owner = 0;
    std::uint32_t edge = 0;
    std::uint32_t incident = no_reference;  ///< the incident edge, when already known
};

// The full separating-axis test: the reference edge (least penetration, with last step's edge
// kept within a small tolerance so that nearly equal candidates do not alternate), or nullopt
// when some edge separates the polygons.
// separating: set to the separating edge when there is one.
std::optional<Reference> choose_reference(const PolygonView& a, const PolygonView& b, std::uint32_t previous_reference,
                                          std::uint32_t& separating, double gap_m) {
    const Axis on_a = best_axis(a, b, gap_m);
    if (on_a.separation_m >= gap_m) {
        separating = make_feature(0, on_a.edge);
        return std::nullopt;
    }
    const Axis on_b = best_axis(b, a, gap_m);
    if (on_b.separation_m >= gap_m) {
        separating = make_feature(1, on_b.edge);
        return std::nullopt;
    }
    Reference r{on_a.separation_m >= on_b.separation_m ? 0u : 1u, 0};
    r.edge = r.owner == 0 ? on_a.edge : on_b.edge;
    if (previous_reference != no_reference) {
        const std::uint32_t prev_owner = feature_owner(previous_reference);
        const std::uint32_t prev_edge = feature_vertex(previous_reference);
        const PolygonView& ref = prev_owner == 0 ? a : b;
        const PolygonView& other = prev_owner == 0 ? b : a;
        if (prev_edge < ref.count) {
            const double best = std::max(on_a.separation_m, on_b.separation_m);
            if (edge_separation(ref, prev_edge, other) >= best - reference_tolerance(best)) r = {prev_owner, prev_edge};
        }
    }
    return r;
}

// The largest separation over every edge of both polygons except the two named ones.
double largest_other_separation(const PolygonView& a, const PolygonView& b, std::uint32_t skip1, std::uint32_t skip2) {
    double largest = -std::numeric_limits<double>::infinity();
    for (std::uint32_t owner = 0; owner < 2; ++owner) {
        const PolygonView& poly = owner == 0 ? a : b;
        const PolygonView& other = owner == 0 ? b : a;
        for (std::uint32_t i = 0; i < poly.count; ++i) {
            const std::uint32_t f = make_feature(owner, i);
            if (f != skip1 && f != skip2) largest = std::max(largest, edge_separation(poly, i, other));
        }
    }
    return largest;
}

// The fast path for a pair in lasting contact: if last step's reference edge is still within
// the hysteresis tolerance of the incident edge and of every other edge (their separations at
// the last full test, moved by at most the drift since), the full test would choose it again,
// so it is the reference. Returns nullopt when the full test is needed, and a reference with owner 2
// when the reference edge now separates the polygons.
std::optional<Reference> cached_reference(const PolygonView& a, const PolygonView& b, std::uint32_t previous_reference,
                                          const AxisCache& cache, double gap_m) {
    if (previous_reference == no_reference || !(cache.others_max_separation_m < INFINITY)) return std::nullopt;
    const Reference r{feature_owner(previous_reference), feature_vertex(previous_reference)};
    const PolygonView& ref = r.owner == 0 ? a : b;
    const PolygonView& inc = r.owner == 0 ? b : a;
    if (r.edge >= ref.count) return std::nullopt;
    const double separation = edge_separation(ref, r.edge, inc);
    if (separation >= gap_m) return Reference{2, 0};  // touching counts as apart, as in the full test
    // The incident edge cannot have changed while the bodies have turned, relative to each
    // other, by less than half its margin (each dot product moves by at most that angle; the
    // 1e-12 covers the round-off of the turned normals).
    std::uint32_t i1 = feature_vertex(cache.incident);
    if (!(2.0 * cache.turn_rad + 1e-12 < cache.incident_margin)) {
        i1 = incident_edge(inc, ref.normals[r.edge]).edge;
        if (make_feature(1u - r.owner, i1) != cache.incident) return std::nullopt;
    }
    // Every other edge separates by at most bound. The full test keeps last step's edge when it
    // is within the tolerance of the best, and the tolerance only grows as the best falls, so
    // meeting it against bound (>= the best, < gap: no edge separates) is enough (x - tol(x)
    // grows with x).
    const double bound = std::max(edge_separation(inc, i1, ref), cache.others_max_separation_m + cache.drift_m);
    if (bound < gap_m && separation >= bound - reference_tolerance(bound)) return Reference{r.owner, r.edge, i1};
    return std::nullopt;
}

}  // namespace

bool separated_by_cached_edge(const PolygonView& a, const PolygonView& b, const AxisCache& cache, double gap_m) {
    if (cache.separating == no_reference) return false;
    const std::uint32_t owner = feature_owner(cache.separating);
    const std::uint32_t edge = feature_vertex(cache.separating);
    const PolygonView& poly = owner == 0 ? a : b;
    return edge < poly.count && edge_separation(poly, edge, owner == 0 ? b : a) >= gap_m;
}

bool collide_polygons(const PolygonView& a, const PolygonView& b, std::uint32_t previous_reference,
                      ContactManifold& manifold, AxisCache* cache, double gap_m) {
    manifold.count = 0;
    // A pair kept apart by an edge last step is most likely still apart along it.
    if (cache && separated_by_cached_edge(a, b, *cache, gap_m)) return false;
    std::optional<Reference> chosen = cache ? cached_reference(a, b, previous_reference, *cache, gap_m) : std::nullopt;
    const bool cached = chosen.has_value();
    std::uint32_t separating = no_reference;
    if (!cached) chosen = choose_reference(a, b, previous_reference, separating, gap_m);
    if (chosen && chosen->owner == 2) separating = previous_reference;  // last step's reference now separates
    if (!chosen || chosen->owner == 2) {
        if (cache) {
            *cache = AxisCache{};
            cache->separating = separating;
        }
        return false;
    }
    const std::uint32_t owner = chosen->owner;
    const std::uint32_t edge = chosen->edge;
    const PolygonView& ref = owner == 0 ? a : b;
    const PolygonView& inc = owner == 0 ? b : a;
    const std::uint32_t inc_owner = 1u - owner;

    const std::uint32_t r1 = edge;
    const std::uint32_t r2 = next_corner(edge, ref.count);
    const Vec2 n = ref.normals[edge];
    const Vec2 v1 = ref.vertices[r1];
    const Vec2 v2 = ref.vertices[r2];
    const Vec2 tangent = perp(n);  // along the edge from v1 to v2 (n is the edge turned clockwise)

    std::uint32_t i1 = chosen->incident;
    if (!cached) {
        const IncidentEdge incident = incident_edge(inc, n);
        i1 = incident.edge;
        if (cache) {
            cache->separating = no_reference;
            cache->incident = make_feature(inc_owner, i1);
            cache->incident_margin = incident.margin;
            cache->others_max_separation_m = largest_other_separation(a, b, make_feature(owner, edge), cache->incident);
            cache->drift_m = 0.0;
            cache->turn_rad = 0.0;
        }
    }
    const std::uint32_t i2 = next_corner(i1, inc.count);
    const ClipPoint segment[2] = {{inc.vertices[i1], make_feature(inc_owner, i1)},
                                  {inc.vertices[i2], make_feature(inc_owner, i2)}};
    ClipPoint once[2];
    ClipPoint twice[2];
    // Keep what lies between the side planes through v1 and v2.
    if (clip_segment(segment, once, -tangent, -dot(tangent, v1), make_feature(owner, r1)) < 2) return false;
    if (clip_segment(once, twice, tangent, dot(tangent, v2), make_feature(owner, r2)) < 2) return false;

    manifold.normal = owner == 0 ? n : -n;
    manifold.reference = make_feature(owner, edge);
    for (const ClipPoint& c : twice) {
        const double overlap = -dot(n, c.p - v1);
        if (overlap <= -gap_m) continue;
        ContactGeometry& g = manifold.points[manifold.count++];
        g.point_m = c.p + (0.5 * overlap) * n;
        g.overlap_m = overlap;
        g.feature = c.feature;
    }
    manifold.stiffness_scale = 1.0;
    if (manifold.count == 2) {
        // Compared squared first: the square roots are needed only for a short overlap.
        const Vec2 along_reference = v2 - v1;
        const Vec2 along_incident = inc.vertices[i2] - inc.vertices[i1];
        const double shorter_squared = std::min(dot(along_reference, along_reference), dot(along_incident, along_incident));
        const Vec2 span = manifold.points[1].point_m - manifold.points[0].point_m;
        const double span_squared = dot(span, span);
        if (span_squared < 1e-4 * shorter_squared)
            manifold.stiffness_scale = std::sqrt(span_squared) / (0.01 * std::sqrt(shorter_squared));
    }
    return manifold.count > 0;
}

}  // namespace blockdem
