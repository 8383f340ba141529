#pragma once
// Narrow phase of two convex polyhedra: the contact points where they overlap, each keyed by the
// pair of features that makes it, so that its shear history can be kept from step to step
// (contact/contact_table_3d.hpp). The 3-D counterpart of geometry/polygon_contact.hpp's
// corner-to-edge points.
//
// How. The separating-axis theorem for convex polyhedra: they are apart if and only if their
// projections are apart on a face normal of either or on the cross product of an edge of each.
// When no axis separates them, the axis of least overlap is the contact normal:
//   - a face normal: that face is the reference face. The incident face is the other body's face
//     most opposed to it; it is clipped by the reference face's side planes (Sutherland-Hodgman),
//     and each clipped corner below the reference plane is a point, with the overlap its depth:
//     a corner of the incident face (vertex-to-face), an incident edge crossing a reference edge
//     (edge-to-edge), or a corner of the reference face inside the incident face (face-to-vertex);
//     each point carries its corner's share of the stiffness, by the clipped polygon's turn there
//     (geometry/corner_share_3d.hpp), so that a corner cut in two or cut off changes nothing at once;
//   - an edge-edge axis (two edges crossing, as when two boxes meet edge on edge): one point, at
//     the middle of the two edges' closest points, the overlap their distance along the axis.
// Face axes are preferred unless an edge axis overlaps clearly less (by 5%), and A's face unless
// B's overlaps clearly less, so that the reference does not flip between steps on round-off and
// the keys stay the same while the bodies rest on each other. This is the scheme of the game
// engines' box and hull colliders (Gregorius, "The separating axis test between convex
// polyhedra", GDC 2013), written here for the DEM's per-point history. Two boxes (both with a
// box frame) take the same axes in the same order, each projected from the centres and half
// lengths instead of the vertices: the same overlaps to round-off, for a fraction of the cost; a
// box's reference face clips in its own frame (geometry/box_face_clip_3d.hpp), with the same
// corners, order and keys as the general clip.
#include <cstdint>
#include <vector>

#include "geometry/box_frame_3d.hpp"
#include "geometry/polyhedron.hpp"
#include "geometry/polyhedron_edges_3d.hpp"

namespace blockdem {

/// A feature of a polyhedron: its kind in the top two bits, its number in the others.
enum class FeatureKind3d : std::uint32_t { vertex = 0, edge = 1, face = 2 };
constexpr std::uint32_t feature_3d(FeatureKind3d kind, std::uint32_t index) {
    return (static_cast<std::uint32_t>(kind) << 30) | index;
}
constexpr FeatureKind3d feature_kind(std::uint32_t feature) { return static_cast<FeatureKind3d>(feature >> 30); }
constexpr std::uint32_t feature_index(std::uint32_t feature) { return feature & ((1u << 30) - 1u); }

/// A polyhedron as it lies in the world now: its shape, and where its vertices, face normals and
/// edge directions turned into the world frame and its centroid are kept (the step's pose writes
/// them once a step per body). Only pointers: the step writes a body's view when the arrays it
/// points into are made, not at every step (world/step_3d.cpp, size_pose_arrays).
struct PosedPolyhedron {
    const Polyhedron* shape = nullptr;
    const PolyhedronEdges* edges = nullptr;
    const Vec3* vertices_m = nullptr;  ///< [m] world frame, one per shape vertex
    /// Outward unit normals, world frame, one per face; null for a box whose normals are its
    /// directions to the bit (box->normals_are_directions), whose normals are read from its
    /// directions (face_normal).
    const Vec3* face_normals = nullptr;
    const Vec3* directions = nullptr;  ///< unit edge directions, world frame, one per edges->directions
    const Vec3* centroid_m = nullptr;  ///< [m] where its centroid is kept
    const BoxFrame3d* box = nullptr;   ///< its box frame (geometry/box_frame_3d.hpp); null: use the general test
};

/// Face f's outward normal of a box whose normals are its directions to the bit
/// (BoxFrame3d::normals_are_directions): its direction face_direction[f], turned over for a face
/// along minus it. Turning -d gives exactly minus turning d (round-to-nearest is symmetric) and a
/// sign flip is exact, so this is the turned normal's bits.
inline Vec3 box_face_normal(const PosedPolyhedron& p, std::uint32_t f) {
    const Vec3 d = p.directions[p.box->face_direction[f]];
    return p.box->face_sign[f] > 0.0 ? d : -d;
}

/// Face f's outward normal, world frame: the stored one, or a box's from its directions where
/// none is stored.
inline Vec3 face_normal(const PosedPolyhedron& p, std::uint32_t f) {
    return p.face_normals != nullptr ? p.face_normals[f] : box_face_normal(p, f);
}

/// One contact point between a and b.
struct ContactGeometry3d {
    Vec3 point_m;               ///< [m] midway between the two surfaces
    Vec3 normal;                ///< unit, from a to b
    double overlap_m = 0.0;     ///< [m] > 0
    std::uint32_t feature_a = 0;///< feature_3d of a
    std::uint32_t feature_b = 0;///< feature_3d of b
    double stiffness_share = 1.0;  ///< [-] its share of kn and ks (geometry/corner_share_3d.hpp); 1 edge on edge
};

/// A corner of the polygon being clipped: where it is, what made it, and the line it runs along
/// to the next corner (an edge of the incident face, or a side of the reference face).
struct ClipCorner3d {
    Vec3 point_m;
    std::uint32_t feature_incident = 0;  ///< feature of the incident body, or of the reference for its own corners
    std::uint32_t feature_reference = 0; ///< feature of the reference body
    std::uint32_t line_after = 0;        ///< feature_3d(edge, k) of the incident body, or of the reference side
    bool line_is_reference = false;
};

/// Scratch arrays kept by the caller so that a step allocates nothing in steady state.
struct ContactScratch3d {
    std::vector<ClipCorner3d> polygon;
    std::vector<ClipCorner3d> clipped;
    std::vector<double> heights_m2;  ///< [m^2] the corners' heights over a side plane, times the side's length
    std::vector<Vec3> corners_m;     ///< [m] the clipped polygon's corners, for their shares
    std::vector<double> shares;      ///< [-] their stiffness shares
    std::vector<std::uint8_t> quarter_turns;  ///< 1 where a corner is a box face's own (a right angle)
};

/// The general face clip: inc's face inc_face clipped by the side planes of ref's face ref_face
/// (Sutherland-Hodgman, one side at a time in the face's corner order; a corner within 1e-9 of a
/// side's length outside it counts as inside). scratch.polygon gets the clipped corners in order
/// round the polygon. The narrow phase takes it unless geometry/box_face_clip_3d.hpp applies.
void clip_by_face_sides(const PosedPolyhedron& ref, std::uint32_t ref_face, const PosedPolyhedron& inc,
                        std::uint32_t inc_face, ContactScratch3d& scratch);

/// Appends the contact points of a and b to out, sorted by (feature_a, feature_b); returns how
/// many (0 when they do not overlap).
std::size_t polyhedron_contact_3d(const PosedPolyhedron& a, const PosedPolyhedron& b, ContactScratch3d& scratch,
                                  std::vector<ContactGeometry3d>& out);

}  // namespace blockdem
