#pragma once
// Convex polygons: validation, orientation and mass properties (per unit thickness).
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// Area, centroid and second moment of area of a polygon.
struct PolygonProperties {
    double area_m2 = 0.0;        ///< [m^2]
    Vec2 centroid_m;             ///< [m]
    double polar_moment_m4 = 0.0;///< [m^4] integral of |r - centroid|^2 dA
};

/// Area, centroid and polar second moment about the centroid; vertices counter-clockwise.
PolygonProperties polygon_properties(const std::vector<Vec2>& vertices);

/// Least width of a convex polygon [m]: the least distance between two parallel lines that
/// hold it. (One of the two lines carries an edge, so it is the least over edges of the farthest
/// corner from that edge's line.)
double least_width(const std::vector<Vec2>& vertices);

/// Signed area [m^2]: positive when the vertices run counter-clockwise.
double signed_area(const std::vector<Vec2>& vertices);

/// Why the polygon is not a valid strictly convex counter-clockwise polygon, or nullopt if it is.
/// Detects: fewer than 3 vertices, repeated vertices, no area (all on one line), clockwise order,
/// reflex or straight corners (non-convex), and self-intersection (a winding above one turn).
std::optional<std::string> convexity_problem(const std::vector<Vec2>& vertices);

/// The same check for vertices as a user lists them, in either orientation: a clockwise list is
/// checked in reverse order, and the message says that it ran clockwise and numbers the vertices
/// by their position in the list as written (from 0), not in the reversed order.
std::optional<std::string> listed_vertices_problem(const std::vector<Vec2>& listed);

/// The vertices counter-clockwise: reversed when they run clockwise.
std::vector<Vec2> counter_clockwise(std::vector<Vec2> vertices);

/// The four corners of a width x height rectangle centred at center, rotated by rotation_rad.
std::vector<Vec2> rectangle_vertices(double width_m, double height_m, Vec2 center_m, double rotation_rad);

/// Outward unit normal of edge i (from vertex i to vertex i+1) of a counter-clockwise polygon.
inline Vec2 edge_normal(Vec2 from, Vec2 to) {
    const Vec2 d = normalized(to - from);
    return {d.y, -d.x};
}

}  // namespace blockdem
