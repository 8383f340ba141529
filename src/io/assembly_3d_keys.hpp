#pragma once
// The keys of the generated 3-D assemblies (docs/scenario.md, "Three dimensions"): a rock mass
// cut by joint sets (type = "rock_mass") and a random packing in a box container
// (type = "random_packing"). Each returns its bodies as vertex lists, built into bodies by
// io/scenario_3d.cpp as every other body is, and a line saying what was built.
#include <string>
#include <vector>

#include "geometry/vec3.hpp"
#include "io/toml_reader.hpp"
#include "world/world_3d.hpp"

namespace blockdem {

struct GeneratedBody3d {
    std::string name;
    BodyKind3d kind = BodyKind3d::dynamic;
    std::vector<Vec3> vertices_m;  ///< [m] world frame at t = 0, every one a corner of the hull
    double density_kg_m3 = 0.0;    ///< [kg/m^3]
};

struct GeneratedAssembly3d {
    std::vector<GeneratedBody3d> bodies;
    std::string note;  ///< what was built: counts, slivers merged, volume fraction
};

/// [[assemblies]] type = "rock_mass": a box (region_min, region_max) or a convex polyhedron
/// (region_vertices) cut by [[assemblies.joint_sets]] (dip_direction_deg, dip_deg, spacing,
/// origin); the blocks whose centroid lies below `base` or that have a face on a region face
/// named in `fixed` are the ground (kind `ground`, fixed by default), the others dynamic.
/// Blocks named NAME_1 ... in order of their centroids (z, then y, then x).
GeneratedAssembly3d read_rock_mass_3d(TableReader& t, const std::string& name);

/// [[assemblies]] type = "random_packing": `count` boxes or hulls (scenes/random_packing_3d.hpp)
/// in the container's inside (container_min, container_max), from `seed`; the container's floor
/// and walls (NAME_floor, NAME_wall_west/east/south/north) unless container = "none".
GeneratedAssembly3d read_random_packing_3d(TableReader& t, const std::string& name);

}  // namespace blockdem
