#include "scenes/random_packing_3d.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include <fmt/format.h>

#include "geometry/polyhedron.hpp"
#include "geometry/quaternion.hpp"

namespace blockdem::scenes {
namespace {

constexpr double pi = std::numbers::pi;
// The gap between neighbouring cells' bounding spheres, as a fraction of a cell.
constexpr double gap_fraction = 1e-3;
// A hull enclosing less than this fraction of its sphere is drawn again: its points bunched on
// one side make a sliver, whose stable time step would be tiny.
constexpr double min_hull_fill = 0.05;
constexpr int max_redraws = 1000;

// Uniform in [0, 1) from the generator's top 53 bits (the same on every platform).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform(rng); }

// A uniformly distributed orientation (Shoemake 1992, "Uniform random rotations").
Quaternion random_orientation(std::mt19937_64& rng) {
    const double u1 = uniform(rng), u2 = uniform(rng), u3 = uniform(rng);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return normalized(Quaternion{b * std::cos(2.0 * pi * u3), a * std::sin(2.0 * pi * u2), a * std::cos(2.0 * pi * u2),
                                 b * std::sin(2.0 * pi * u3)});
}

// The largest bounding-sphere diameter a body within the limits can have [m].
double largest_diameter_m(const RandomPacking3dDef& def) {
    return def.shape == PackedShape::box ? std::sqrt(3.0) * def.max_size_m : def.max_size_m;
}

// A body's vertices about the centre of its bounding sphere, unturned.
std::vector<Vec3> draw_shape(const RandomPacking3dDef& def, std::mt19937_64& rng) {
    if (def.shape == PackedShape::box) {
        const Vec3 edges{uniform(rng, def.min_size_m, def.max_size_m), uniform(rng, def.min_size_m, def.max_size_m),
                         uniform(rng, def.min_size_m, def.max_size_m)};
        return box_vertices(edges, {});
    }
    for (int attempt = 0; attempt < max_redraws; ++attempt) {
        const double radius_m = 0.5 * uniform(rng, def.min_size_m, def.max_size_m);
        std::vector<Vec3> points;
        for (int k = 0; k < def.hull_points; ++k) {
            const double z = uniform(rng, -1.0, 1.0), phi = uniform(rng, 0.0, 2.0 * pi);
            const double r = std::sqrt(1.0 - z * z);
            points.push_back(radius_m * Vec3{r * std::cos(phi), r * std::sin(phi), z});
        }
        try {
            const double volume_m3 = polyhedron_properties(convex_polyhedron(points)).volume_m3;
            if (volume_m3 >= min_hull_fill * 4.0 / 3.0 * pi * radius_m * radius_m * radius_m) return points;
        } catch (const std::invalid_argument&) {
            // Points too close to tell apart or four on one circle: draw again.
        }
    }
    throw std::invalid_argument(fmt::format("no hull of {} points with a volume found in {} draws", def.hull_points,
                                            max_redraws));
}

}  // namespace

PackingGrid3d packing_grid_3d(const RandomPacking3dDef& def) {
    PackingGrid3d g;
    g.cell_m = largest_diameter_m(def) * (1.0 + gap_fraction);
    const Vec3 inside = def.container_max_m - def.container_min_m;
    g.nx = static_cast<int>(std::floor(inside.x / g.cell_m));
    g.ny = static_cast<int>(std::floor(inside.y / g.cell_m));
    g.nz = static_cast<int>(std::floor(inside.z / g.cell_m));
    return g;
}

RandomPacking3d random_packing_3d(const RandomPacking3dDef& def) {
    if (!(def.min_size_m > 0.0 && def.min_size_m <= def.max_size_m))
        throw std::invalid_argument("the sizes must satisfy 0 < min_size <= max_size");
    if (def.shape == PackedShape::hull && def.hull_points < 4)
        throw std::invalid_argument("a hull needs at least 4 points");
    const PackingGrid3d g = packing_grid_3d(def);
    if (def.count > g.cells())
        throw std::invalid_argument(fmt::format(
            "{} bodies do not fit: the container holds {} x {} x {} = {} cells of {:g} m (one body each, the "
            "bounding sphere of the largest body the sizes allow)",
            def.count, g.nx, g.ny, g.nz, g.cells(), g.cell_m));
    const Vec3 inside = def.container_max_m - def.container_min_m;
    // The grid centred across the floor, from the floor up.
    const Vec3 first_cell_m = def.container_min_m + Vec3{0.5 * (inside.x - g.nx * g.cell_m),
                                                         0.5 * (inside.y - g.ny * g.cell_m), 0.0};
    const double gap_m = gap_fraction * largest_diameter_m(def);
    std::mt19937_64 rng(def.seed);
    RandomPacking3d packing;
    for (std::size_t n = 0; n < def.count; ++n) {
        const std::size_t per_layer = static_cast<std::size_t>(g.nx) * g.ny;
        const std::size_t k = n / per_layer, j = (n % per_layer) / g.nx, i = n % g.nx;
        const Vec3 cell_centre_m =
            first_cell_m + g.cell_m * Vec3{i + 0.5, j + 0.5, k + 0.5};
        const std::vector<Vec3> shape = draw_shape(def, rng);
        const Quaternion turn = random_orientation(rng);
        double radius_m = 0.0;
        for (Vec3 v : shape) radius_m = std::max(radius_m, length(v));
        const double play_m = std::max(0.0, 0.5 * g.cell_m - radius_m - 0.5 * gap_m);
        const Vec3 centre_m = cell_centre_m + Vec3{uniform(rng, -play_m, play_m), uniform(rng, -play_m, play_m),
                                                   uniform(rng, -play_m, play_m)};
        std::vector<Vec3> body;
        for (Vec3 v : shape) body.push_back(centre_m + rotate(turn, v));
        packing.solids_volume_m3 += polyhedron_properties(convex_polyhedron(body)).volume_m3;
        packing.bodies_m.push_back(std::move(body));
    }
    packing.volume_fraction = packing.solids_volume_m3 / (inside.x * inside.y * inside.z);
    return packing;
}

std::vector<std::vector<Vec3>> packing_container_3d(const RandomPacking3dDef& def, double thickness_m) {
    const Vec3 lo = def.container_min_m, hi = def.container_max_m;
    const Vec3 inside = hi - lo;
    const Vec3 mid = 0.5 * (lo + hi);
    const double t = thickness_m;
    return {
        box_vertices({inside.x + 2.0 * t, inside.y + 2.0 * t, t}, {mid.x, mid.y, lo.z - 0.5 * t}),
        box_vertices({t, inside.y + 2.0 * t, inside.z}, {lo.x - 0.5 * t, mid.y, mid.z}),
        box_vertices({t, inside.y + 2.0 * t, inside.z}, {hi.x + 0.5 * t, mid.y, mid.z}),
        box_vertices({inside.x, t, inside.z}, {mid.x, lo.y - 0.5 * t, mid.z}),
        box_vertices({inside.x, t, inside.z}, {mid.x, hi.y + 0.5 * t, mid.z}),
    };
}

}  // namespace blockdem::scenes
