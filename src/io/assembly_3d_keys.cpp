#include "io/assembly_3d_keys.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>

#include "geometry/joint_set_3d.hpp"
#include "geometry/polyhedron.hpp"
#include "geometry/polyhedron_cut.hpp"
#include "io/assembly_keys.hpp"
#include "io/scenario_keys.hpp"
#include "io/vec3_keys.hpp"
#include "scenes/random_packing_3d.hpp"

namespace blockdem {
namespace {

// Distances below this fraction of the region's size count as zero (the hull's own rule,
// geometry/polyhedron.cpp), so that a joint through a vertex or along a face cuts nothing off.
constexpr double relative_tolerance = 1e-9;
// Refused above this many blocks (or joints across the region): a typo in a spacing, not a model.
constexpr double max_blocks = 1e6;

const std::vector<std::string> face_names = {"west", "east", "south", "north", "bottom", "top"};

// A region face's name: the direction its outward normal is nearest to (x east, y north, z up).
std::string face_direction(Vec3 n) {
    const Vec3 a{std::abs(n.x), std::abs(n.y), std::abs(n.z)};
    if (a.x >= a.y && a.x >= a.z) return n.x < 0.0 ? "west" : "east";
    if (a.y >= a.z) return n.y < 0.0 ? "south" : "north";
    return n.z < 0.0 ? "bottom" : "top";
}

Polyhedron read_region_3d(TableReader& t) {
    const bool as_box = t.has("region_min") || t.has("region_max");
    if (as_box && t.has("region_vertices"))
        t.fail("region_vertices", "give either region_min and region_max (a box) or region_vertices, not both");
    try {
        if (!as_box) return convex_polyhedron(vec3_list(t, "region_vertices"));
        const Vec3 lo = vec3(t, "region_min", " ([x, y, z] of the region's lowest corner in m)");
        const Vec3 hi = vec3(t, "region_max", " ([x, y, z] of the region's highest corner in m)");
        if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
            t.fail("region_max", "must be above region_min in x, y and z");
        return convex_polyhedron(box_vertices(hi - lo, 0.5 * (lo + hi)));
    } catch (const std::invalid_argument& e) {
        t.fail(as_box ? "region_max" : "region_vertices", fmt::format("is not a convex polyhedron: {}", e.what()));
    }
}

JointSet3d read_joint_set(TableReader t) {
    JointSet3d s;
    s.dip_direction_deg = t.number("dip_direction_deg");
    if (!(s.dip_direction_deg >= 0.0 && s.dip_direction_deg < 360.0))
        t.fail("dip_direction_deg", "must be in [0, 360) degrees, clockwise from north (+y)");
    s.dip_deg = t.number("dip_deg");
    if (!(s.dip_deg >= 0.0 && s.dip_deg <= 90.0)) t.fail("dip_deg", "must be in [0, 90] degrees below the horizontal");
    s.spacing_m = t.positive("spacing");
    s.origin_m = optional_vec3(t, "origin").value_or(Vec3{});
    t.reject_unknown_keys();
    return s;
}

double largest_distance_m(const std::vector<Vec3>& v) {
    Vec3 mean;
    for (Vec3 p : v) mean += p;
    mean = (1.0 / static_cast<double>(v.size())) * mean;
    double size = 0.0;
    for (Vec3 p : v) size = std::max(size, length(p - mean));
    return size;
}

// The region's faces' names, each checked against the region: a name no face has is refused.
std::set<std::size_t> read_fixed_faces(TableReader& t, const Polyhedron& region) {
    std::set<std::size_t> fixed;
    if (!t.has("fixed")) return fixed;
    const toml::array* names = t.raw().get_as<toml::array>("fixed");
    if (!names) t.fail("fixed", fmt::format("must be a list of face names: {}", fmt::join(face_names, ", ")));
    for (const toml::node& entry : *names) {
        const auto word = entry.value<std::string>();
        if (!word || std::find(face_names.begin(), face_names.end(), *word) == face_names.end())
            t.fail("fixed", fmt::format("'{}' is not a face name; the names: {} (the direction the face's outward "
                                        "normal is nearest to)",
                                        word.value_or("?"), fmt::join(face_names, ", ")));
        bool found = false;
        for (std::size_t f = 0; f < region.faces.size(); ++f)
            if (face_direction(region.face_normals[f]) == *word) {
                fixed.insert(f);
                found = true;
            }
        if (!found) t.fail("fixed", fmt::format("the region has no face facing {}", *word));
    }
    return fixed;
}

}  // namespace

GeneratedAssembly3d read_rock_mass_3d(TableReader& t, const std::string& name) {
    const Polyhedron region = read_region_3d(t);
    const std::vector<TableReader> set_tables = t.table_array("joint_sets");
    if (set_tables.empty()) t.fail("joint_sets", "a rock mass needs at least one [[assemblies.joint_sets]]");
    std::vector<Plane3d> planes;
    double cells = 1.0, smallest_spacing_m = INFINITY;
    for (TableReader st : set_tables) {
        const JointSet3d set = read_joint_set(st);
        std::size_t count = 0;
        try {
            count = joint_plane_count(set, region.vertices_m);
        } catch (const std::invalid_argument& e) {
            st.fail("spacing", e.what());
        }
        cells *= static_cast<double>(count + 1);
        if (cells > max_blocks)
            st.fail("spacing", fmt::format("the joint sets so far would cut the region into up to {:g} blocks (above "
                                           "{:g}): a spacing too small?",
                                           cells, max_blocks));
        check_block_budget(st, "spacing", cells, "the joint sets so far, each cutting the region at its spacing",
                           bytes_per_block_3d);
        const std::vector<Plane3d> joints = joint_planes(set, region.vertices_m);
        planes.insert(planes.end(), joints.begin(), joints.end());
        smallest_spacing_m = std::min(smallest_spacing_m, set.spacing_m);
    }
    const double tolerance_m = relative_tolerance * largest_distance_m(region.vertices_m);
    // Default: a thousandth of the smallest joint spacing's cube, or of the region when the
    // joints are farther apart than the region is large.
    const double cube_m3 = smallest_spacing_m * smallest_spacing_m * smallest_spacing_m;
    const double min_volume_m3 = t.optional_positive("min_block_volume")
                                     .value_or(1e-3 * std::min(cube_m3, polyhedron_properties(region).volume_m3));
    const std::set<std::size_t> fixed_faces = read_fixed_faces(t, region);
    const std::optional<double> base_m = t.optional_number("base");
    const std::string ground = t.choice("ground", {"fixed", "driven"}, "fixed");
    const double density = t.positive("density");

    CutIntoBlocks cut = cut_into_blocks(cut_polyhedron_of(region, 0), planes, region.faces.size(), min_volume_m3,
                                        tolerance_m);
    struct Block {
        Vec3 centroid_m;
        std::vector<Vec3> vertices_m;
        bool ground = false;
    };
    std::vector<Block> blocks;
    for (const CutPolyhedron& c : cut.blocks) {
        Block b;
        b.vertices_m = cut_polyhedron_vertices(c, tolerance_m);
        b.centroid_m = polyhedron_properties(convex_polyhedron(b.vertices_m)).centroid_m;
        for (const CutFace& f : c.faces) b.ground = b.ground || fixed_faces.count(f.plane);
        b.ground = b.ground || (base_m && b.centroid_m.z < *base_m);
        blocks.push_back(std::move(b));
    }
    std::sort(blocks.begin(), blocks.end(), [](const Block& a, const Block& b) {
        return std::tie(a.centroid_m.z, a.centroid_m.y, a.centroid_m.x) <
               std::tie(b.centroid_m.z, b.centroid_m.y, b.centroid_m.x);
    });
    GeneratedAssembly3d out;
    std::size_t grounded = 0;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const BodyKind3d kind = !blocks[i].ground ? BodyKind3d::dynamic
                                : ground == "fixed" ? BodyKind3d::fixed
                                                    : BodyKind3d::driven;
        grounded += blocks[i].ground ? 1 : 0;
        out.bodies.push_back({fmt::format("{}_{}", name, i + 1), kind, std::move(blocks[i].vertices_m), density});
    }
    out.note = fmt::format("rock mass '{}': {} blocks ({} {}, {} free) from {} joints", name, out.bodies.size(),
                           grounded, ground, out.bodies.size() - grounded, planes.size());
    if (cut.slivers_merged > 0)
        out.note += fmt::format("; {} cuts not made because a piece would be below min_block_volume = {:g} m^3 (the "
                                "sliver stays with its neighbour)",
                                cut.slivers_merged, min_volume_m3);
    return out;
}

GeneratedAssembly3d read_random_packing_3d(TableReader& t, const std::string& name) {
    scenes::RandomPacking3dDef def;
    def.count = static_cast<std::size_t>(t.whole_number("count", 1, 1'000'000));
    check_block_budget(t, "count", static_cast<double>(def.count), fmt::format("count = {}", def.count), bytes_per_block_3d);
    const std::string shape = t.choice("shape", {"box", "hull"}, "box");
    def.shape = shape == "box" ? scenes::PackedShape::box : scenes::PackedShape::hull;
    def.min_size_m = t.positive("min_size");
    def.max_size_m = t.positive("max_size");
    if (def.max_size_m < def.min_size_m) t.fail("max_size", "must be at least min_size");
    if (def.shape == scenes::PackedShape::hull)
        def.hull_points = static_cast<int>(t.whole_number_or("hull_points", 12, 4, 64));
    def.container_min_m = vec3(t, "container_min", " ([x, y, z] of the container's inside, lowest corner, in m)");
    def.container_max_m = vec3(t, "container_max", " ([x, y, z] of the container's inside, highest corner, in m)");
    const Vec3 inside = def.container_max_m - def.container_min_m;
    if (!(inside.x > 0.0 && inside.y > 0.0 && inside.z > 0.0))
        t.fail("container_max", "must be above container_min in x, y and z");
    def.seed = static_cast<std::uint64_t>(t.whole_number_or("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
    const double density = t.positive("density");
    const std::string container = t.choice("container", {"driven", "fixed", "none"}, "driven");
    const double thickness_m = t.optional_positive("wall_thickness").value_or(def.max_size_m);

    const scenes::PackingGrid3d grid = scenes::packing_grid_3d(def);
    if (def.count > grid.cells())
        t.fail("count", fmt::format("{} bodies do not fit: the container holds {} x {} x {} = {} cells of {:g} m, one "
                                    "body each (the bounding sphere of the largest body max_size allows)",
                                    def.count, grid.nx, grid.ny, grid.nz, grid.cells(), grid.cell_m));
    scenes::RandomPacking3d packing;
    try {
        packing = scenes::random_packing_3d(def);
    } catch (const std::invalid_argument& e) {
        t.fail(def.shape == scenes::PackedShape::hull ? "hull_points" : "count", e.what());
    }
    GeneratedAssembly3d out;
    for (std::size_t i = 0; i < packing.bodies_m.size(); ++i)
        out.bodies.push_back({fmt::format("{}_{}", name, i + 1), BodyKind3d::dynamic, std::move(packing.bodies_m[i]),
                              density});
    if (container != "none") {
        const char* parts[] = {"floor", "wall_west", "wall_east", "wall_south", "wall_north"};
        const std::vector<std::vector<Vec3>> boxes = scenes::packing_container_3d(def, thickness_m);
        for (std::size_t i = 0; i < boxes.size(); ++i)
            out.bodies.push_back({fmt::format("{}_{}", name, parts[i]),
                                  container == "fixed" ? BodyKind3d::fixed : BodyKind3d::driven, boxes[i], density});
    }
    out.note = fmt::format("random packing '{}': {} {} bodies (seed {}), volume fraction {:.4f} of the container's "
                           "inside ({:.6g} of {:.6g} m^3)",
                           name, def.count, shape, def.seed, packing.volume_fraction, packing.solids_volume_m3,
                           inside.x * inside.y * inside.z);
    return out;
}

}  // namespace blockdem
