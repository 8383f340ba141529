#pragma once
// A set of parallel, fully persistent joints as geologists give it: dip direction and dip, and
// the spacing between joints (docs/3d.md, "Rock mass and random packing").
//
// The geological convention: the dip direction is the azimuth of the line of steepest descent
// on the joint, in degrees clockwise from north, with north = +y and east = +x; the dip is the
// angle of that line below the horizontal. The joint's upward normal (its pole) is then
//   n = (sin(dip) sin(dip_direction), sin(dip) cos(dip_direction), cos(dip)),
// so that dip 0 gives a vertical normal and dip 90, dip direction 90 (a vertical joint striking
// north) the normal along x.
#include <cstddef>
#include <vector>

#include "geometry/polyhedron_cut.hpp"
#include "geometry/vec3.hpp"

namespace blockdem {

struct JointSet3d {
    double dip_direction_deg = 0.0;  ///< [deg] clockwise from north (+y), in [0, 360)
    double dip_deg = 0.0;            ///< [deg] below the horizontal, in [0, 90]
    double spacing_m = 1.0;          ///< [m] between neighbouring joints, along the normal
    Vec3 origin_m;                   ///< [m] a point on one joint of the set
};

/// The set's upward unit normal (the pole of its joints).
Vec3 joint_normal(double dip_direction_deg, double dip_deg);

/// How many joints of the set lie between the lowest and the highest of the points along the
/// normal (those on either end included): the size joint_planes will have, without making them.
/// Throws std::invalid_argument when the joints' numbers from the origin exceed 2^52.
std::size_t joint_plane_count(const JointSet3d& set, const std::vector<Vec3>& region_vertices_m);

/// Those joints, in order along the normal.
std::vector<Plane3d> joint_planes(const JointSet3d& set, const std::vector<Vec3>& region_vertices_m);

}  // namespace blockdem
