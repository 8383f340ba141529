#pragma once
// A simple polygon (convex or not, no holes) as a few convex pieces that tile it exactly: ear
// clipping into triangles, then removing diagonals wherever the two pieces they separate merge
// into a convex polygon (Hertel and Mehlhorn 1983; at most four times the minimum number of
// pieces). The assembly generators cut every piece separately, so a non-convex region (a slope
// with a toe bench, an L-shaped wall) still gives convex blocks; the diagonals that remain act
// as extra joints.
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

/// Convex counter-clockwise pieces whose union is the polygon (either orientation accepted).
/// Throws std::invalid_argument for fewer than 3 corners, zero area, or a self-crossing outline
/// that ear clipping cannot finish.
std::vector<std::vector<Vec2>> convex_decomposition(std::vector<Vec2> polygon);

/// Convex counter-clockwise pieces of a simple polygon (either orientation), for bodies
/// (geometry/outline.hpp): cut from its reflex corners, along diagonals or along the line of an
/// edge at the corner carried on to the boundary (a new corner there), each cut the one that
/// makes most of its ends convex, then the shortest; the cuts that are not needed are removed
/// as above. Fewer and fatter pieces than ear clipping for the outlines masons draw (a keyed
/// brick: 5 rectangles, not 10 pieces with slivers; an L: its 2 rectangles). Throws
/// std::invalid_argument for fewer than 3 corners or zero area.
std::vector<std::vector<Vec2>> convex_pieces_cut_at_reflex_corners(std::vector<Vec2> polygon);

/// True when the counter-clockwise polygon is convex (straight corners allowed).
bool is_convex(const std::vector<Vec2>& polygon);

}  // namespace blockdem
