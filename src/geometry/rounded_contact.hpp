#pragma once
// Narrow phase with rounded corners ([contact] rounding = r, as UDEC's rounding length): every
// corner of a polygon is an arc of radius r. A rounded polygon is its core (the polygon with
// every edge moved inward by r) swept by a disk of radius r, so its outline is the drawn
// polygon with its corners cut into arcs tangent to both edges.
//
// Why: two sharp corners meeting have no defined normal. The sharp model (polygon_contact.hpp)
// picks one of the edges, so the force on a corner-to-corner impact points along an edge normal
// chosen by a tolerance, and it jumps when the choice changes. With arcs the normal is the line
// between the two arcs' centres (the closest points of the cores): always defined, and it turns
// continuously as the bodies move.
//
// Method, on the cores A' and B' (convex): the separating-axis test over the edge normals gives
// the edge with the largest separation s (reference edge; two rounded bodies touch when s < 2r).
// - Face contact: if the deepest part of the other core lies within the reference edge's extent,
//   the closest distance is s and the normal is the edge's. The incident edge is clipped to the
//   reference edge's extent as in the sharp model; each clipped point is a contact point of
//   overlap 2r - (its distance to the reference edge's line). Feature ids as in the sharp model.
// - Corner contact: otherwise the closest points of the cores are two corners (or a corner and
//   an edge); one point, overlap 2r - d, normal along the line between them, midway between the
//   surfaces; its feature id names the corner (of the incident body when both are corners).
// - Cores that overlap (overlap > 2r, beyond what a rigid-block model should see) fall back on
//   the sharp model's face contact on the cores, overlaps plus 2r.
// The two cases meet continuously: a face contact whose two points close up (a block sliding off
// a corner) is softened to half its stiffness as the points merge, which is the stiffness of the
// single corner point that follows it (the sharp model softens it to zero instead, because there
// the contact really ends).
//
// The cores' corners are made from the polygons' current corners and edge normals when needed
// (a core corner is v_i - r (n_{i-1} + n_i) / (1 + n_{i-1} . n_i): a few operations per corner);
// a lasting face contact needs only the four corners of its two edges (see the AxisCache).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/polygon_contact.hpp"

namespace blockdem {

/// How far the corner of the core lies inside the drawn corner between edges with outward unit
/// normals normal_before and normal_after, for rounding r [m]: the core corner is on both edges'
/// lines moved inward by r, so with o = r (n_before + n_after) / (1 + n_before . n_after),
/// n . o = r for both normals, and the core corner is v - o. (Inline, and the one expression:
/// the body geometry makes every corner's offset once a step with it, world/step.cpp, and the
/// narrow phase's own, for a polygon without them, must be the same bits.)
[[gnu::always_inline]] inline Vec2 rounded_corner_offset(Vec2 normal_before, Vec2 normal_after, double r) {
    return (r / (1.0 + dot(normal_before, normal_after))) * (normal_before + normal_after);
}

/// A body may be rounded with r only if r < rounding_width_fraction x its least width (the core
/// then keeps at least half of the body's width) and no edge of its core vanishes.
inline constexpr double rounding_width_fraction = 0.25;

/// Why a convex counter-clockwise polygon (corners and outward unit edge normals, any frame)
/// cannot be rounded with radius rounding_m, or nullopt. least_width_m: the polygon's least width.
std::optional<std::string> rounding_problem(const std::vector<Vec2>& vertices, const std::vector<Vec2>& normals,
                                            double least_width_m, double rounding_m);

/// The contact of the rounded polygons a and b (rounding_m > 0): fills manifold like
/// collide_polygons (normal from a to b, points, reference, stiffness_scale). previous_reference:
/// last step's reference edge for this pair. cache: as collide_polygons' AxisCache, on the cores
/// (the caller adds drift and turn each step); a pair in lasting face contact skips the full test
/// with the same result, bit for bit. Its separating edge, for a pair apart, is an edge that kept
/// the cores 2r or more apart: the caller's test of it on the drawn polygons is then conservative
/// (drawn polygons apart means rounded ones apart). Returns true if they touch.
/// gap_m: as in collide_polygons, points whose rounded surfaces are apart by less than this still
/// count, with a negative overlap (a bonded joint opening: contact/bonded_pairs.hpp).
/// seam_a, seam_b: per corner, 1 for a corner of a concave body's part that is no arc of the body
/// (geometry/rounded_outline.hpp; nullptr: none): a corner contact whose closest point is one is
/// not made, as the neighbouring part makes it.
bool collide_rounded(const PolygonView& a, const PolygonView& b, double rounding_m, std::uint32_t previous_reference,
                     ContactManifold& manifold, AxisCache& cache, double gap_m = 0.0, const std::uint8_t* seam_a = nullptr,
                     const std::uint8_t* seam_b = nullptr);

}  // namespace blockdem
