#pragma once
// Checks of a block outline as drawn, before it becomes a body: enough corners, an area, and
// edges that do not cross (a simple polygon). Convexity is not asked for here: a concave
// outline goes on to the body's own validation (world/world.cpp, and the convex decomposition
// where it is available). Messages give coordinates in the drawing's units so that the user
// finds the spot in the drawing.
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// Blocks with more corners than this are refused: a drawn block has a few to a few hundred,
/// and the crossing check costs the square of the count.
inline constexpr std::size_t max_outline_vertices = 10000;

/// Drops consecutive repeated corners (a CAD polyline often repeats a snapped point).
std::vector<Vec2> without_repeated_vertices(std::vector<Vec2> vertices);

/// Why vertices (a closed outline, last corner not repeating the first, no consecutive
/// repeats) cannot be a block, or nullopt: fewer than 3 corners, too many, no area, an edge
/// folding back on the one before, two edges crossing or touching. unit names the drawing's
/// length unit in messages.
std::optional<std::string> drawn_outline_problem(const std::vector<Vec2>& vertices, const std::string& unit);

}  // namespace blockdem
