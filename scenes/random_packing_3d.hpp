#pragma once
// A random packing of convex polyhedra in a box container (issue 15), placed by a deterministic
// sequential rule, not by a dynamic settle: the container's floor is cut into a grid of cubic
// cells, each large enough for the bounding sphere of the largest body the limits allow; cells are
// filled layer by layer from the bottom, one body each, turned at random and moved at random
// within its cell as far as its own bounding sphere allows. Bodies in different cells cannot
// overlap, and a gap of 1e-3 of a cell keeps them (and the walls) apart at the start.
//
// Random numbers: std::mt19937_64 (its sequence is fixed by the C++ standard) turned into
// uniform doubles by taking its top 53 bits, so a seed gives the same bodies on every platform
// and compiler (std::uniform_real_distribution's algorithm is not specified).
#include <cstdint>
#include <vector>

#include "geometry/vec3.hpp"

namespace blockdem::scenes {

enum class PackedShape : std::uint8_t {
    box,   ///< edges each drawn in [min_size, max_size]
    hull,  ///< the hull of `hull_points` points on a sphere whose diameter is drawn in [min_size, max_size]
};

struct RandomPacking3dDef {
    std::size_t count = 10;
    PackedShape shape = PackedShape::box;
    double min_size_m = 0.1;     ///< [m]
    double max_size_m = 0.2;     ///< [m]
    int hull_points = 12;        ///< points of a hull body (4 or more)
    Vec3 container_min_m;        ///< [m] the container's inside, lowest corner
    Vec3 container_max_m{1.0, 1.0, 1.0};  ///< [m] highest corner
    std::uint64_t seed = 1;
};

/// The cells that fit in the container (columns along x and y, layers along z): the most bodies
/// the rule can place.
struct PackingGrid3d {
    int nx = 0, ny = 0, nz = 0;
    double cell_m = 0.0;  ///< [m] a cell's side
    std::size_t cells() const { return static_cast<std::size_t>(nx) * ny * nz; }
};
PackingGrid3d packing_grid_3d(const RandomPacking3dDef& def);

struct RandomPacking3d {
    std::vector<std::vector<Vec3>> bodies_m;  ///< each body's vertices [m], world frame, all corners of its hull
    double solids_volume_m3 = 0.0;            ///< [m^3] the bodies' volumes summed
    double volume_fraction = 0.0;             ///< [-] of the container's inside
};

/// The packing. Throws std::invalid_argument when `count` bodies do not fit (saying how many
/// do), or the limits are inconsistent.
RandomPacking3d random_packing_3d(const RandomPacking3dDef& def);

/// The container: a floor under the inside and four walls around it, `thickness_m` thick, as
/// high as the inside; boxes' vertices [m]: floor, then walls at -x, +x, -y, +y.
std::vector<std::vector<Vec3>> packing_container_3d(const RandomPacking3dDef& def, double thickness_m);

}  // namespace blockdem::scenes
