#pragma once
// Narrow phase: the contact points between two convex polygons, in Cundall's corner-to-edge
// model. Every contact point is a corner of one body pressed into an edge of the other; a block
// lying flat on the table touches at its two bottom corners, a rocking block at one.
//
// Method: separating-axis test over the edge normals of both polygons. The edge with the least
// penetration is the reference edge; its normal is the contact normal. The edge of the other
// polygon facing it most directly (the incident edge) is clipped to the reference edge's extent,
// and every clipped point below the reference edge is a contact point (at most 2). A point is
// either a corner of the incident polygon or, where clipping cut the incident edge, the point
// facing a corner of the reference polygon. Its feature id names that corner, so a contact keeps
// its identity (and its shear history) whichever of two parallel edges is chosen as reference.
//
// Near-degenerate cases: when two candidate reference edges penetrate almost equally (parallel
// faces, corner against corner) the previous step's reference edge is kept unless another edge
// penetrates clearly less (hysteresis), so the normal does not flip back and forth between steps.
// When the overlap shrinks to a point (a block sliding off the end of a step, two corners
// meeting, bricks whose joints line up), the two points would carry full force until they
// vanish together; instead the contact is softened by stiffness_scale = min(1, L / l), L the
// distance between the two points and l = 1% of the shorter of the two edges, so its force
// fades continuously to zero.
#include <cmath>
#include <cstdint>

#include "geometry/vec2.hpp"

namespace blockdem {

/// A convex counter-clockwise polygon in world coordinates, viewed without owning it.
struct PolygonView {
    const Vec2* vertices = nullptr;  ///< [m]
    const Vec2* normals = nullptr;   ///< outward unit normal of edge i (vertex i to i+1)
    std::uint32_t count = 0;
    /// [m] optional, for the rounded narrow phase: corner i's rounded_corner_offset at the
    /// caller's rounding, made from these normals (null: made from them when needed)
    const Vec2* corner_offsets_m = nullptr;
};

/// A feature id: the polygon that owns the corner (0 = a, 1 = b) and the corner's index.
constexpr std::uint32_t make_feature(std::uint32_t owner, std::uint32_t vertex) { return (owner << 16) | vertex; }
constexpr std::uint32_t feature_owner(std::uint32_t feature) { return feature >> 16; }
constexpr std::uint32_t feature_vertex(std::uint32_t feature) { return feature & 0xffffu; }

/// One contact point between polygons a and b.
struct ContactGeometry {
    Vec2 point_m;              ///< [m] midway between the two surfaces
    double overlap_m = 0.0;    ///< [m] > 0 in compression
    std::uint32_t feature = 0; ///< make_feature(owner, corner)
};

/// Room for a manifold's two points, left unset until the narrow phase writes a point: the
/// narrow phase makes a manifold for every pair it tests, and zeroing both points each time
/// (their members have default values) cost 1 % of a jointed wall's step. Only the points below
/// the manifold's count are ever written or read. (A union member, so that no constructor runs;
/// not std::byte storage behind std::launder, which kept GCC from holding the points in
/// registers and cost as much as the zeroing saved.)
class ManifoldPoints {
public:
    ManifoldPoints() {}  // (user-provided so that ContactManifold{} leaves the points unset too)
    ContactGeometry& operator[](std::uint32_t i) { return slots_[i]; }
    const ContactGeometry& operator[](std::uint32_t i) const { return slots_[i]; }

private:
    union {
        ContactGeometry slots_[2];
    };
};

/// The contact between polygons a and b: a shared normal (from a to b) and 0 to 2 points.
struct ContactManifold {
    Vec2 normal;                  ///< unit normal pointing from a to b
    std::uint32_t count = 0;      ///< number of points (0: separated)
    ManifoldPoints points;        ///< points[0] to points[count - 1]; the others unset
    std::uint32_t reference = 0;  ///< make_feature(owner, edge) of the reference edge, for hysteresis
    double stiffness_scale = 1.0; ///< [-] multiplies the contact's stiffnesses (short overlaps, see above)
};

/// No reference edge from a previous step.
inline constexpr std::uint32_t no_reference = 0xffffffffu;

/// What a pair in lasting contact keeps so that most steps skip the full separating-axis test:
/// at the last full test, the largest separation of every edge but the reference and the
/// incident edge, and how far any separation may have moved since (the caller adds each step's
/// bound of the two bodies' relative motion to drift_m). With the reference still penetrating
/// no more than the incident edge and than others_max + drift, the full test would choose the
/// same reference, so the result is the same as without the cache, bit for bit. Likewise the
/// incident edge is kept while the bodies have turned (turn_rad, added by the caller) by less
/// than half the margin by which it beat the other edges. A pair that is apart keeps the edge
/// that separated it (the full test's, or last step's reference edge when that now separates)
/// and tests that one first.
struct AxisCache {
    // (separating first: a pair that stays apart reads nothing else.)
    std::uint32_t separating = no_reference;    ///< for a pair apart: the edge that separated it last
    std::uint32_t incident = no_reference;      ///< make_feature(owner, edge) of the incident edge then
    double others_max_separation_m = INFINITY;  ///< [m]; infinity: nothing cached
    double drift_m = 0.0;                       ///< [m]
    double incident_margin = 0.0;               ///< [-] dot-product lead of the incident edge then
    double turn_rad = 0.0;                      ///< [rad] bound on the relative rotation since
};

/// True if the edge that separated a and b last step (cache.separating) still separates them:
/// collide_polygons would then return no points and change nothing.
/// (gap_m: as in collide_polygons.)
bool separated_by_cached_edge(const PolygonView& a, const PolygonView& b, const AxisCache& cache, double gap_m = 0.0);

/// Fills manifold with the contact points of a and b. previous_reference: the reference edge
/// chosen at the last step for this pair (no_reference if none). cache: optional, see AxisCache.
/// gap_m: points apart by less than this still count, with a negative overlap (a bonded joint
/// that opens within what its bond carries: contact/bonded_pairs.hpp). The cache holds geometry
/// only, so it serves whatever gap a pair has from step to step.
/// Returns true if they touch.
bool collide_polygons(const PolygonView& a, const PolygonView& b, std::uint32_t previous_reference,
                      ContactManifold& manifold, AxisCache* cache = nullptr, double gap_m = 0.0);

}  // namespace blockdem
