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
#include <array>
#include <cstdint>
#include <vector>

#include "geometry/polyhedron_contact_3d.hpp"

namespace blockdem {

/// The largest incident face the rectangle clip takes: a face of k corners clipped by four sides
/// has at most k + 4.
constexpr std::size_t box_clip_most_incident_corners = 8;

/// A corner of the rectangle clip's polygon in the reference face's frame (u, v in its plane, w
/// along its outward normal, from its corner 0), with ClipCorner3d's features. No default values:
/// the clip's arrays are written before they are read, and zeroing them cost a sixth of the clip.
struct BoxClipCorner3d {
    double u_m;  ///< [m]
    double v_m;  ///< [m]
    double w_m;  ///< [m] height over the reference plane (negative below it: the depth is -w_m)
    std::uint32_t feature_incident;
    std::uint32_t feature_reference;
    std::uint32_t line_after;
    bool line_is_reference;
};

/// The rectangle clip's polygon left in the reference face's frame. Why (docs/performance.md,
/// "Branch clip3d"): the narrow phase needs a corner's depth (-w) and, for the shares, only turns,
/// which a rotation keeps (to round-off), so only the points below the plane are lifted to the world.
struct BoxFaceClip3d {
    static constexpr std::size_t most_corners = box_clip_most_incident_corners + 4;
    Vec3 origin_m;  ///< [m] the reference face's corner 0
    Vec3 e_u;       ///< one of the box's directions in the face's plane
    Vec3 e_v;       ///< n x e_u
    Vec3 n;         ///< the face's outward normal
    std::size_t count = 0;
    const BoxClipCorner3d* corners = nullptr;  ///< count corners in order round the polygon (into buffers)
    std::array<BoxClipCorner3d, most_corners> buffers[2];  ///< the clip's two polygons, one side to the next

    /// The world point of (u, v, w).
    Vec3 world_m(double u_m, double v_m, double w_m) const { return origin_m + u_m * e_u + v_m * e_v + w_m * n; }
};

/// clip_by_box_face's polygon, left in the reference face's frame (clip.corners). Returns false
/// as clip_by_box_face does. A box's face of 4 corners is cut in one pass by the first side that
/// cuts it (docs/performance.md "Branch clip1p"), the passes going on from the next side where that
/// cut is not the whole clip ("Sixteenth session"); any other face takes the passes: the passes'
/// polygon to the bit either way (unit/test_box_face_clip_3d checks it).
bool clip_box_face_in_frame(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                            std::uint32_t inc_face, BoxFaceClip3d& clip);

/// What the narrow phase takes for two boxes: clip_box_face_in_frame's polygon when some corner of
/// the incident face lies below the reference plane (w < 0), and no corner (count 0, returning
/// true) when none does, since then no corner of the polygon does either and there is no point to
/// make. Why: a fifth of a brick wall's face clips (its head joints, touching to round-off) give
/// no point (docs/performance.md, "Branch face5").
bool clip_box_face_where_below(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                               std::uint32_t inc_face, BoxFaceClip3d& clip);

/// The Sutherland-Hodgman passes alone, side by side (what clip_box_face_in_frame stands for).
bool clip_box_face_by_passes(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                             std::uint32_t inc_face, BoxFaceClip3d& clip);

/// The one-pass clip alone: false when it cannot decide as the passes would (two sides or more
/// cut the face, or a side after the cutting one holds a corner within half its slack of it or
/// has a half slack within 1e-12 of the coordinates).
bool clip_box_face_in_one_pass(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                               std::uint32_t inc_face, BoxFaceClip3d& clip);

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
