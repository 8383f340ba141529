#pragma once
// Cutting convex polygons by straight lines, the one operation the assembly generators need:
// a joint is a line that splits every block it crosses in two; a Voronoi cell is the region
// clipped by the half-planes of the bisectors to its neighbours; a non-convex region is split
// into convex pieces first (convex_decomposition.hpp), so that every cut of a piece stays convex.
//
// Round-off: a cut through (or within round-off of) an existing corner must not leave a
// near-zero edge or a straight corner behind, which convexity_problem() would reject and which
// would give the contact detection a degenerate edge; tidy_convex_polygon() removes both.
#include <optional>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// The half-plane { x : dot(normal, x) <= offset } (normal need not be unit length).
struct HalfPlane {
    Vec2 normal;          ///< points out of the kept side
    double offset = 0.0;  ///< [m * |normal|]
};

/// The half-plane on the side of p where dot(direction, x - point) <= 0.
inline HalfPlane half_plane_through(Vec2 point_m, Vec2 direction) { return {direction, dot(direction, point_m)}; }

/// Keeps the part of a convex counter-clockwise polygon inside the half-plane (empty if none).
std::vector<Vec2> clip_convex(const std::vector<Vec2>& polygon, const HalfPlane& keep);

/// Splits a convex polygon by the line dot(normal, x) = offset into the part below (<=) and the
/// part above; a part may be empty. Both parts use the same intersection points, so they share
/// the cut edge exactly.
struct ConvexSplit {
    std::vector<Vec2> below;
    std::vector<Vec2> above;
};
ConvexSplit split_convex(const std::vector<Vec2>& polygon, const HalfPlane& line);

/// Removes repeated corners (closer than tolerance_m) and straight corners (whose turn is below
/// a relative 1e-9), so that the result passes convexity_problem(). Returns nullopt when fewer
/// than 3 corners or no area are left (a sliver). tolerance_m: about 1e-12 of the polygon size.
std::optional<std::vector<Vec2>> tidy_convex_polygon(const std::vector<Vec2>& polygon, double tolerance_m);

/// Area of a polygon [m^2] (counter-clockwise positive).
double polygon_area(const std::vector<Vec2>& polygon);

}  // namespace blockdem
