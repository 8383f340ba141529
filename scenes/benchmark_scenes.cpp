// The jointed rock slope and the Voronoi rockfill of the benchmarks (scenes/assemblies.hpp),
// sized by an approximate block count so that one code path serves 1e2 to 1e6 blocks.
#include <algorithm>
#include <cmath>

#include "geometry/polygon.hpp"
#include "laws/restitution.hpp"
#include "scenes/assemblies.hpp"

namespace blockdem::scenes {
namespace {

ContactParameters rock_contact() {
    return {.kn_N_m = 1e9, .ks_N_m = 1e9, .mu = 0.6, .h_n = damping_ratio_rebound(0.5), .h_s = 0.2};
}

Model shaken_base(const Polygon& region, double duration_s) {
    Model m;
    m.settings.duration_s = duration_s;
    m.contact = MaterialPairs::uniform(rock_contact());
    m.table_motion.horizontal = SineMotion{0.3 * 9.81, 0.5, 0.0, 0.0, 0.0};
    double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY;
    for (Vec2 v : region) {
        lo_x = std::min(lo_x, v.x);
        hi_x = std::max(hi_x, v.x);
        lo_y = std::min(lo_y, v.y);
    }
    const double pad = 0.1 * (hi_x - lo_x);
    BodyDef table;
    table.name = "table";
    table.kind = BodyKind::driven;
    table.vertices_m = {{lo_x - pad, lo_y - pad}, {hi_x + pad, lo_y - pad}, {hi_x + pad, lo_y}, {lo_x - pad, lo_y}};
    table.density_kg_m3 = 2600.0;
    m.bodies.push_back(table);
    return m;
}

}  // namespace

Model rock_slope_scene(int blocks, double duration_s) {
    // Section area about 0.55 H^2 (H the slope height); blocks of about spacing^2 / sin(80 deg).
    const double height = 10.0;
    const Polygon region = slope_region(0.3 * height, height, 60.0, 0.5 * height, 0.6 * height);
    const double area = std::abs(signed_area(region));
    const double spacing = std::sqrt(area / std::max(blocks, 1) * std::sin(100.0 * 3.14159265358979 / 180.0));
    RockMassSpec spec;
    spec.region_m = region;
    // Bedding dipping 20 deg into the slope and steep cross joints, as examples/assemblies/rock_slope.toml.
    spec.joint_sets = {JointSet{-20.0, spacing, 0.2, 3.0, {0.0, 0.0}}, JointSet{80.0, spacing, 0.2, 3.0, {0.1, 0.0}}};
    spec.seed = 2024;
    spec.min_block_area_m2 = 0.1 * spacing * spacing;  // slivers would set a tiny time step
    Model m = shaken_base(region, duration_s);
    BlockStyle style;
    style.name_prefix = "rock";
    style.density_kg_m3 = 2600.0;
    std::vector<BodyDef> rocks = as_bodies(jointed_rock_mass(spec).polygons, style);
    // The foundation below the toe and the back of the section move with the base (UDEC-style
    // boundary blocks); the rest is free to slide and topple out of the face.
    const double back = region[1].x - 2.0 * spacing;
    set_kind_inside(rocks, {{-1e3, -1e3}, {1e3, -1e3}, {1e3, 0.0}, {-1e3, 0.0}}, BodyKind::driven);
    set_kind_inside(rocks, {{back, -1e3}, {1e3, -1e3}, {1e3, 1e3}, {back, 1e3}}, BodyKind::driven);
    for (BodyDef& b : rocks) m.bodies.push_back(std::move(b));
    return m;
}

Model rockfill_scene(int blocks, double duration_s) {
    const double width = 20.0;
    const double height = 10.0;
    VoronoiSpec spec;
    spec.region_m = {{0.0, 0.0}, {width, 0.0}, {width, height}, {0.0, height}};
    spec.cell_size_m = std::sqrt(width * height / std::max(blocks, 1));
    spec.jitter = 0.8;  // below 1 keeps seeds apart, so no cell is a sliver
    spec.seed = 7;
    Model m = shaken_base(spec.region_m, duration_s);
    BlockStyle style;
    style.name_prefix = "fill";
    style.density_kg_m3 = 2000.0;
    for (BodyDef& b : as_bodies(voronoi_packing(spec).polygons, style)) m.bodies.push_back(std::move(b));
    return m;
}

}  // namespace blockdem::scenes
