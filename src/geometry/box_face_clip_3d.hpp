#pragma once
// The narrow phase's face clip (geometry/polyhedron_contact_3d.cpp) when the reference face is a
// box's rectangle: the incident face is clipped by the rectangle's four sides in the reference
// face's own frame, where each side plane is a bound on one coordinate. Why: the general clip
// takes each corner's height over each side plane as a 3-D dot product and copies 3-D corner
// records between growing arrays; here a height is one subtraction and the polygon lives in a
// fixed array. It is the same Sutherland-Hodgman clip, side by side in the reference face's
// corner order, with the same slack, crossings and features, so it gives the general clip's
// corners (to round-off) in the same order round the polygon and with the same keys
// (unit/test_box_face_clip_3d checks it over random poses).
#include <cstdint>
#include <vector>

#include "geometry/polyhedron_contact_3d.hpp"

namespace blockdem {

/// The largest incident face the rectangle clip takes: a face of k corners clipped by four sides
/// has at most k + 4.
constexpr std::size_t box_clip_most_incident_corners = 8;

/// Whether clip_by_box_face can clip inc's face inc_face against ref's face: ref is a box (its
/// box frame says so) and the incident face has at most box_clip_most_incident_corners corners.
bool box_face_clip_applies(const PosedPolyhedron& ref, const PosedPolyhedron& inc, std::uint32_t inc_face);

/// inc's face inc_face clipped by the side planes of ref's rectangular face ref_face (a corner
/// within 1e-9 of a side's length outside it counts as inside): polygon gets the clipped corners,
/// world frame, in order round the polygon, each with the features that make it. Returns false,
/// polygon then unspecified, when round-off made the polygon gain more corners than a convex one
/// can (the caller then takes the general clip).
bool clip_by_box_face(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                      std::uint32_t inc_face, std::vector<ClipCorner3d>& polygon);

}  // namespace blockdem
