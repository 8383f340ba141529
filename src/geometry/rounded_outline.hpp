#pragma once
// The convex parts of a concave body with rounded corners ([contact] rounding = r): only the
// outline's own convex corners are arcs, and a face that a cut between two parts meets stays
// straight across the seam.
//
// Why: rounding each convex part at all its corners (rounded_contact.hpp) rounds the corners
// where a cut meets the outline too, so a face split by a cut has a groove at the seam, and a
// block sliding across it drops into it. The rounded body is the outline opened by a disk of
// radius r: its core E is the outline with every edge moved inward by r (a concave polygon),
// and the body is E swept by the disk. E is cut into convex cores (outline_parts), and each
// core, swept by the disk, is what the rounded narrow phase sees: it is given as the core with
// its edges moved back out by r, a convex polygon whose own core is that core exactly. The
// cores tile E, so their swept shapes cover the opened outline, and their faces meet end to end
// along the outline (no groove, no face counted twice).
//
// Seams: a corner of a core that is not a convex corner of E (the end of a cut, on a face or at
// a reflex corner) is not an arc of the body; the closest point of another body's core to such a
// corner always lies on the neighbouring core's face as well, so a corner contact there belongs
// to the neighbour and the rounded narrow phase makes none (collide_rounded's seam flags). A
// convex corner of E shared by two cores (a cut ending at a corner) is an arc of the first only.
#include <cstdint>
#include <vector>

#include "geometry/vec2.hpp"

namespace blockdem {

struct RoundedOutlineParts {
    std::vector<std::vector<Vec2>> parts;        ///< [m] each convex, counter-clockwise: a core moved out by r
    std::vector<std::vector<std::uint8_t>> seam;  ///< per corner of each part: 1 if it is no arc of the body
};

/// The parts of the counter-clockwise simple outline (outline_problem gives nullopt) rounded with
/// rounding_m > 0. Throws std::invalid_argument saying why when the moved-in outline is not a
/// simple polygon with every edge kept (the radius too large for a corner or an edge).
RoundedOutlineParts rounded_outline_parts(const std::vector<Vec2>& outline, double rounding_m);

}  // namespace blockdem
