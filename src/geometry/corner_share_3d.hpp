#pragma once
// How much of a contact's stiffness each corner of a face-clipped overlap polygon carries
// (docs/3d.md, "The ledger on a shaken wall").
//
// Why. A face contact is the incident face clipped by the reference face's side planes; each
// corner below the reference plane is a contact point. With a full kn at every corner, the
// stiffness jumps when the polygon gains or loses a corner: two bricks of equal width lying flush
// have an incident edge running along a reference side plane, turned by ~1e-7 rad, and the clip
// cuts it anywhere along its length. That cut is a corner, born or gone with the depth it has
// there, so kn d^2 / 2 appears or vanishes at once, tens of thousands of times on a shaken wall.
//
// The share. Corner i weighs w_i = turn_i / (pi / 2), turn_i the exterior (turning) angle of the
// polygon at that corner: the angle between the side that arrives there and the side that leaves.
// It is measured in the polygon's own plane (the clipped polygon lies in the incident face), so a
// box face's corner weighs 1 however the face is tilted to the reference. A convex polygon's
// exterior angles sum to 2 pi, so the weights of a polygon always sum to 4: a rectangle's corners
// weigh 1 each (box on box as before: "kn is per corner of a square patch"), a corner on a
// near-straight side (the flicker's cut) weighs ~0, and a corner cut in two by a side plane
// splits its weight between the two cuts continuously. Corners that coincide (a side between
// them shorter than 1e-9 of the longest, whose direction is round-off) share their group's
// turn equally. A polygon of fewer than 3 distinct corners follows the same rule: a segment's
// two ends turn by pi (weight 2 each), a point is the whole turn (4, shared by the corners there).
// The shares depend only on where the corners are, not on which features made them, so a
// polygon from any clip (the general one, a box face's rectangle clip) gets the same shares.
// Cost (docs/performance.md, "Branch np3d"): a corner the caller knows to be a right angle (a box
// face's own corner, kept by the clip) is given 1 without a turn; a turn near a quarter or near
// zero, as a brick wall's cuts are, takes the arctangent's series rather than atan2; the last
// corner not known to be a right angle is not measured but takes what the others leave of 4
// (branch clip1p: the same share to round-off, one turn fewer a polygon).
#include <cstddef>
#include <cstdint>

#include "geometry/vec3.hpp"

namespace blockdem {

/// shares[i] = corner i's share of the contact stiffness (its turn over pi / 2), for the count
/// corners of a plane convex polygon in order round it (either way round). quarter_turns, when
/// given, marks (nonzero) the corners whose turn the caller knows to be a right angle: a box face's
/// own corner that the clip kept, both its sides lying along the face's edges. Such a corner
/// weighs exactly 1, not 1 to round-off, and costs no turn (when no side of the polygon is short;
/// otherwise every corner is measured, as the groups need).
void corner_shares_3d(const Vec3* corners_m, std::size_t count, double* shares,
                      const std::uint8_t* quarter_turns = nullptr);

}  // namespace blockdem
