#pragma once
// A polyhedron that is a rectangular box, as the narrow phase's box-box separating-axis test
// needs it (geometry/polyhedron_contact_3d.cpp): its three edge directions with the half lengths
// along them, and which direction and side each face is. Why: a box's projection on an axis is
// its centre's plus sum h_i |d_i . axis| (3 products instead of 8 vertices), and its face planes
// are the centre's plus h_i, so the 6 + 6 face axes and 9 edge axes of two boxes cost a few dozen
// products (Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996), where the vertex projections
// of the general test cost a few hundred. Found once per shape.
#include <array>
#include <cstdint>

#include "geometry/polyhedron.hpp"
#include "geometry/polyhedron_edges_3d.hpp"

namespace blockdem {

struct BoxFrame3d {
    bool is_box = false;
    Vec3 half_lengths_m;                  ///< [m] along the edge directions 0, 1, 2 (PolyhedronEdges::directions)
    std::array<std::uint8_t, 6> face_direction{};  ///< per face, the direction its normal lies along
    std::array<double, 6> face_sign{};             ///< per face, +1 when its normal is that direction, -1 against
    /// face_of[i][0]: the face whose normal is +direction i; face_of[i][1]: the one along -i (the
    /// inverse of face_direction and face_sign, so that the narrow phase picks a face per direction).
    std::array<std::array<std::uint8_t, 2>, 3> face_of{};
    /// Every face normal is exactly (to the bit) face_sign times its direction, so that a pose may
    /// take the turned normals from the turned directions: turning -d gives exactly minus turning d
    /// (round-to-nearest is symmetric), so the result is the same bits for 6 fewer turns a box.
    bool normals_are_directions = false;
    /// Per vertex, which corner of the box it is: bit i set when it lies on the + side of
    /// direction i. A pose places the 8 corners as the centre +/- h_i d_i (world/step_3d.cpp).
    std::array<std::uint8_t, 8> vertex_corner{};
    /// Per face, its 4 corners (Polyhedron::faces) and its 4 edges (PolyhedronEdges::face_edges)
    /// in the shape's order: the same numbers, kept here so that the box clip (geometry/
    /// box_face_clip_3d.cpp) reads its reference face's from the frame it reads anyway, not
    /// through the shape's and the edges' vectors of vectors (a heap block a face). 16-bit, not
    /// bytes: a byte's type may alias any object, the clip's doubles too. The incident face's too,
    /// where the incident body is a box: read from its shape, the clip waited on the shape's heap
    /// blocks (docs/performance.md, "Fourteenth session"; "Branch pose8" counted 40 instructions
    /// more a clip for it, on a host where those reads hit the cache).
    std::array<std::array<std::uint16_t, 4>, 6> face_corners{};
    std::array<std::array<std::uint16_t, 4>, 6> face_edges{};
};

/// The box frame of p when p is a box about its centroid (the body frame's origin): 8 vertices, 6
/// faces of 4 corners, 3 mutually perpendicular edge directions, every vertex at +/- the half
/// lengths along them (to 1e-12 of the box's size); otherwise is_box = false and the general test
/// is used.
BoxFrame3d box_frame(const Polyhedron& p, const PolyhedronEdges& edges);

}  // namespace blockdem
