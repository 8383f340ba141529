#pragma once
// Exact clipping of a convex polyhedron by a plane, and a region cut into blocks by many planes:
// the rock mass of issue 15 (docs/3d.md, "Rock mass and random packing").
//
// A convex polyhedron cut by a plane gives two convex polyhedra: each face is clipped by the
// plane (Sutherland-Hodgman), and the points on the plane close each piece with a cap, their 2-D
// hull in the plane. Every face keeps a label of the plane it lies on (a face of the region, a
// joint), so that a block knows its faces' origins (the fixed faces of a slope, the tests).
//
// Robustness: a vertex within `tolerance_m` of the plane counts as on it; it goes, unmoved, to
// both pieces and makes no crossing point, so a plane through a vertex, an edge or a face makes
// no sliver and no repeated point. A crossing point is computed from the edge's two ends in one
// fixed order, so the two faces sharing the edge get the same bits.
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/polyhedron.hpp"
#include "geometry/vec3.hpp"

namespace blockdem {

/// The plane dot(normal, x) = offset_m; normal a unit vector. "Below" is dot(normal, x) < offset_m.
struct Plane3d {
    Vec3 normal;
    double offset_m = 0.0;  ///< [m]
};

/// A face of a cut polyhedron: its corners counter-clockwise seen from outside, and the label of
/// the plane it lies on (the caller's numbering).
struct CutFace {
    std::vector<Vec3> corners_m;  ///< [m]
    std::size_t plane = 0;
};

/// A convex polyhedron as its faces.
struct CutPolyhedron {
    std::vector<CutFace> faces;
};

/// The polyhedron's faces labelled first_label + the face's number.
CutPolyhedron cut_polyhedron_of(const Polyhedron& p, std::size_t first_label);

/// The two pieces of a cut; a piece is absent when the polyhedron lies wholly on the other side
/// (vertices on the plane do not count).
struct HalfSpaceCut {
    std::optional<CutPolyhedron> below;
    std::optional<CutPolyhedron> above;
};

/// Cuts p by the plane; the cap of each piece gets the label plane_label. Vertices within
/// tolerance_m [m] of the plane count as on it.
HalfSpaceCut cut_by_plane(const CutPolyhedron& p, const Plane3d& plane, std::size_t plane_label, double tolerance_m);

/// Volume [m^3] (the divergence theorem over the faces' fans).
double cut_polyhedron_volume(const CutPolyhedron& p);

/// The distinct corners [m] of the faces (a corner shared by several faces listed once).
std::vector<Vec3> cut_polyhedron_vertices(const CutPolyhedron& p, double tolerance_m);

/// Blocks from a region cut by every plane in turn (plane i labelled first_label + i). A cut that
/// would leave a piece below min_volume_m3 is not made for that block (the sliver stays merged
/// with its neighbour, which keeps the block convex); slivers_merged counts them.
struct CutIntoBlocks {
    std::vector<CutPolyhedron> blocks;
    std::size_t slivers_merged = 0;
};

CutIntoBlocks cut_into_blocks(const CutPolyhedron& region, const std::vector<Plane3d>& planes, std::size_t first_label,
                              double min_volume_m3, double tolerance_m);

}  // namespace blockdem
