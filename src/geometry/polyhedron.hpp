#pragma once
// Convex polyhedra: the hull of a vertex list, checked, and its mass properties from volume
// integrals. A 3-D body's shape (docs/3d.md).
//
// Why an own hull rather than Qhull: the bodies here have tens of vertices (a box 8, a 32-sided
// drum 64), and the checks a user needs (a vertex inside the hull or in the middle of a face is
// named as a mistake, not silently dropped as a hull library does) need every supporting plane
// anyway. A plane through three vertices with every vertex on one side of it is a face; the test
// is exact up to a tolerance relative to the body's size, costs O(n^4) at worst and has no
// degenerate cases to special-case (coplanar points are gathered into one face). Measured: a
// 32-sided prism (64 vertices) takes 2.4 ms, a 64-sided one 25 ms, once per body when a model
// is built (bodies of one shape could share it).
#include <cstddef>
#include <vector>

#include "geometry/matrix_3d.hpp"
#include "geometry/quaternion.hpp"
#include "geometry/vec2.hpp"
#include "geometry/vec3.hpp"

namespace blockdem {

/// A convex polyhedron: its vertices and its faces, each a list of vertex indices running
/// counter-clockwise seen from outside (so that the right-hand normal points out).
struct Polyhedron {
    std::vector<Vec3> vertices_m;                   ///< [m]
    std::vector<std::vector<std::size_t>> faces;    ///< vertex indices, counter-clockwise from outside
    std::vector<Vec3> face_normals;                 ///< outward unit normals, one per face
};

/// The convex hull of the vertices, with every vertex a corner of it. Throws
/// std::invalid_argument naming the vertex (by its position in the list, from 0) when the list is
/// not a convex polyhedron: fewer than 4 vertices, two that coincide, all on one line or one
/// plane (no volume), a vertex inside the hull of the others (the set is not convex), or a
/// vertex on a face or an edge of the hull but not at a corner.
Polyhedron convex_polyhedron(const std::vector<Vec3>& vertices_m);

/// The hull as convex_polyhedron, then the faces as the user listed them checked against it:
/// every listed face must be a hull face with its vertices counter-clockwise seen from outside.
/// Throws std::invalid_argument naming the face (from 0) that is inverted (listed clockwise
/// from outside), not a face of the hull, or missing.
Polyhedron convex_polyhedron(const std::vector<Vec3>& vertices_m, const std::vector<std::vector<std::size_t>>& faces);

/// Volume, centroid and inertia per unit density (multiply by the density [kg/m^3] for mass [kg]
/// and inertia [kg m^2]).
struct PolyhedronProperties {
    double volume_m3 = 0.0;  ///< [m^3]
    Vec3 centroid_m;         ///< [m]
    Matrix3d inertia_m5;     ///< [m^5] inertia tensor about the centroid, integral of (|r|^2 1 - r r^T) dV
};

/// The divergence theorem over tetrahedra: each face cut into triangles, each triangle the base
/// of a tetrahedron with its apex at the mean vertex (near the body, for precision far from the
/// origin), and the closed forms of a tetrahedron's volume, first and second moments summed.
PolyhedronProperties polyhedron_properties(const Polyhedron& p);

/// Principal moments and axes of an inertia tensor.
struct PrincipalAxes {
    Vec3 moments;             ///< principal moments, ascending, in the unit of the tensor
    Quaternion orientation;   ///< turns the principal frame into the tensor's frame (the axes as columns)
};

PrincipalAxes principal_axes(const Matrix3d& inertia);

/// The eight corners of a box with edges length_x, length_y, length_z [m] along the axes of
/// orientation, centred at center_m.
std::vector<Vec3> box_vertices(Vec3 lengths_m, Vec3 center_m, Quaternion orientation = {});

/// A prism: the polygon (in the x-y plane, either orientation) extruded from z = 0 to height_m;
/// its base corners first, then the top ones in the same order.
std::vector<Vec3> prism_vertices(const std::vector<Vec2>& polygon_m, double height_m);

}  // namespace blockdem
