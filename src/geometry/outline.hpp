#pragma once
// A body's outline: one simple polygon, convex or not (an L-shaped block, a keyed brick, a
// carved stone). A concave outline is cut into convex parts (geometry/convex_decomposition) that
// move as one rigid body; the narrow phase works on the parts, the outputs draw the outline.
//
// An outline must be simple: its edges meet only at their shared corners. A hole cannot be one
// list of vertices; the usual trick of cutting in to the hole along a slit (a "keyhole") makes
// the outline touch itself, which is refused: the two lips of the slit would be one body with no
// contact between them, which is not what the drawing means.
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// Why a counter-clockwise outline cannot be a body, or nullopt when it can: fewer than 3
/// vertices, two vertices at one place, no area, a straight or folded-back corner, two edges
/// that cross, or a vertex on another edge (the outline touches itself: a keyhole). A convex
/// outline gets convexity_problem's messages.
std::optional<std::string> outline_problem(const std::vector<Vec2>& vertices);

/// The same check for vertices as a user lists them, in either orientation; vertex numbers are
/// positions in the list as written (from 0), as listed_vertices_problem (geometry/polygon.hpp).
std::optional<std::string> listed_outline_problem(const std::vector<Vec2>& listed);

/// The convex parts of a valid counter-clockwise outline (outline_problem gives nullopt): the
/// outline itself when it is convex, else strictly convex counter-clockwise pieces that tile it
/// (straight corners left by the decomposition removed), each passing convexity_problem.
std::vector<std::vector<Vec2>> outline_parts(const std::vector<Vec2>& outline);

/// The convex hull of count points, counter-clockwise, without straight corners (Andrew's
/// monotone chain): what a concave body stands on (its base spans the legs of a Pi-shaped block).
std::vector<Vec2> convex_hull(const Vec2* points, std::size_t count);

}  // namespace blockdem
