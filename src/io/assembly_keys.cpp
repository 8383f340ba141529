#include "io/assembly_keys.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "io/machine_memory.hpp"
#include "scenes/assemblies.hpp"

namespace blockdem {
namespace {

// Bodies are numbered with 32-bit ids; far below that, 1e8 blocks is past any run this code can do.
constexpr double max_assembly_blocks = 1e8;
// Seeds are 64-bit, but TOML numbers are read exactly only up to 2^53.
constexpr std::int64_t max_seed = std::int64_t{1} << 53;

scenes::BlockStyle read_style(TableReader& t) {
    scenes::BlockStyle s;
    s.name_prefix = t.string("name");
    s.material = t.optional_string("material").value_or("default");
    s.density_kg_m3 = t.positive("density");
    s.thickness_m = t.optional_positive("thickness").value_or(1.0);
    s.record = t.boolean_or("record", false);
    return s;
}

std::vector<scenes::Polygon> read_column(TableReader& t) {
    const Vec2 base = t.optional_vec2("base_center").value_or(Vec2{});
    std::vector<Vec2> sizes;
    if (t.has("sizes")) {
        sizes = t.vec2_list("sizes");
        for (const Vec2& s : sizes)
            if (!(s.x > 0.0 && s.y > 0.0)) t.fail("sizes", "every [width, height] must be > 0");
    } else {
        const auto count = t.whole_number("count", 1, static_cast<std::int64_t>(max_assembly_blocks));
        check_block_budget(t, "count", static_cast<double>(count), fmt::format("count = {}", count), bytes_per_block_2d);
        sizes.assign(static_cast<std::size_t>(count), Vec2{t.positive("width"), t.positive("height")});
    }
    return scenes::block_column(sizes, base);
}

// With stepped ends the odd courses are one piece a brick shorter than the wall: a wall not
// longer than a brick would leave them empty (the courses above floating), and a piece below
// min_piece_fraction of a brick has no neighbour to join.
void check_stepped_courses(TableReader& t, const scenes::WallSpec& w) {
    if (!w.stepped_ends || w.courses < 2) return;
    const double odd_length_m = w.length_m - w.brick_length_m;
    const double least_piece_m = std::max(w.min_piece_fraction, 0.0) * w.brick_length_m;
    if (!(odd_length_m > 0.0))
        t.fail("stepped_ends", fmt::format("is true with a length of {:g} m, not more than brick_length {:g} m: the odd courses, "
                                           "half a brick shorter at each end, would hold no brick and the courses above "
                                           "would float; give a longer wall, or stepped_ends = false (half bricks at the ends)",
                                           w.length_m, w.brick_length_m));
    if (odd_length_m < least_piece_m - 1e-9 * w.brick_length_m)  // (the joints' tolerance, scenes/masonry.cpp)
        t.fail("stepped_ends", fmt::format("is true with a length of {:g} m: the odd courses, half a brick shorter at each end, "
                                           "would be one piece {:g} m long, less than min_piece_fraction x brick_length = {:g} m; "
                                           "give a length of at least {:g} m, or stepped_ends = false (half bricks at the ends)",
                                           w.length_m, odd_length_m, least_piece_m, w.brick_length_m + least_piece_m));
}

std::vector<scenes::Polygon> read_wall(TableReader& t) {
    scenes::WallSpec w;
    w.origin_m = t.optional_vec2("origin").value_or(Vec2{});
    w.length_m = t.positive("length");
    w.courses = static_cast<int>(t.whole_number("courses", 1, static_cast<std::int64_t>(max_assembly_blocks)));
    w.brick_length_m = t.optional_positive("brick_length").value_or(w.brick_length_m);
    w.brick_height_m = t.optional_positive("brick_height").value_or(w.brick_height_m);
    w.stepped_ends = t.boolean_or("stepped_ends", false);
    w.min_piece_fraction = t.number_or("min_piece_fraction", w.min_piece_fraction);
    check_stepped_courses(t, w);
    for (TableReader o : t.table_array("openings")) {
        scenes::WallOpening opening{o.number("x"), o.number("y"), o.positive("width"), o.positive("height"),
                                    o.number_or("lintel_bearing", 0.0)};
        if (opening.x_m < 0.0 || opening.x_m + opening.width_m > w.length_m)
            o.fail("x", fmt::format("the opening must lie within the wall's length {} m", w.length_m));
        o.reject_unknown_keys();
        w.openings.push_back(opening);
    }
    const double blocks = scenes::estimated_block_count(w);
    const double per_course = blocks / w.courses;
    check_block_budget(t, per_course >= w.courses ? "length" : "courses", blocks,
                       fmt::format("{} courses x {:.3g} a course, from length / brick_length = {:g} m / {:g} m", w.courses,
                                   per_course, w.length_m, w.brick_length_m), bytes_per_block_2d);
    return scenes::masonry_wall(w);
}

// region = [[x, y], ...] or a [slope] table (scenes::slope_region).
std::vector<Vec2> read_region(TableReader& t) {
    if (auto slope = t.optional_table("slope")) {
        std::vector<Vec2> region = scenes::slope_region(slope->number_or("base_height", 0.0), slope->positive("height"),
                                                        slope->positive("face_angle_deg"), slope->number_or("toe_length", 0.0),
                                                        slope->number_or("crest_length", 0.0));
        slope->reject_unknown_keys();
        if (t.has("region")) t.fail("region", "give either region or [slope], not both");
        return region;
    }
    return t.vec2_list("region");
}

scenes::GeneratedBlocks read_rock_mass(TableReader& t) {
    scenes::RockMassSpec spec;
    spec.region_m = read_region(t);
    spec.seed = static_cast<std::uint64_t>(t.whole_number_or("seed", 1, 0, max_seed));
    spec.min_block_area_m2 = t.number_or("min_block_area", 0.0);
    for (TableReader j : t.table_array("joint_sets")) {
        scenes::JointSet set;
        set.dip_deg = j.number("dip_deg");
        set.spacing_m = j.positive("spacing");
        set.spacing_spread = j.number_or("spacing_spread", 0.0);
        set.dip_spread_deg = j.number_or("dip_spread_deg", 0.0);
        set.origin_m = j.optional_vec2("origin").value_or(Vec2{});
        j.reject_unknown_keys();
        spec.joint_sets.push_back(set);
    }
    if (spec.joint_sets.empty()) t.fail("joint_sets", "a rock mass needs at least one [[assemblies.joint_sets]]");
    for (std::size_t i = 0; i < spec.joint_sets.size(); ++i)
        if (spec.joint_sets[i].spacing_spread < 0.0 || spec.joint_sets[i].spacing_spread >= 1.0)
            t.fail("joint_sets", fmt::format("joint set {}: spacing_spread must be in [0, 1), got {}", i + 1, spec.joint_sets[i].spacing_spread));
    check_block_budget(t, "joint_sets", scenes::estimated_block_count(spec),
                       fmt::format("{} joint set{} across the region at their spacings", spec.joint_sets.size(),
                                   spec.joint_sets.size() == 1 ? "" : "s"), bytes_per_block_2d);
    return scenes::jointed_rock_mass(spec);
}

scenes::GeneratedBlocks read_voronoi(TableReader& t) {
    scenes::VoronoiSpec spec;
    spec.region_m = read_region(t);
    spec.cell_size_m = t.positive("cell_size");
    spec.jitter = t.number_or("jitter", spec.jitter);
    spec.seed = static_cast<std::uint64_t>(t.whole_number_or("seed", 1, 0, max_seed));
    spec.shrink = t.number_or("shrink", 0.0);
    check_block_budget(t, "cell_size", scenes::estimated_block_count(spec),
                       fmt::format("the region's extent in cells of {:g} m", spec.cell_size_m), bytes_per_block_2d);
    return scenes::voronoi_packing(spec);
}

// An arch: span (or radius), rise (default: a semicircle), ring_thickness, voussoirs, and its
// abutments fixed or driven with the table.
std::vector<BodyDef> read_arch(TableReader& t, const scenes::BlockStyle& style) {
    scenes::ArchSpec spec;
    spec.origin_m = t.optional_vec2("origin").value_or(Vec2{});
    const std::optional<double> radius = t.optional_positive("radius");
    const std::optional<double> span = t.optional_positive("span");
    if (radius && span) t.fail("radius", "give either span or radius, not both");
    if (!radius && !span) t.fail("span", "an arch needs its span (or its radius): the centre line's, in m");
    const std::optional<double> rise = t.optional_positive("rise");
    if (radius) {
        const double r = *radius;
        const double f = rise.value_or(r);
        if (f > r) t.fail("rise", fmt::format("must be <= radius = {} m (a semicircle at most), got {}", r, f));
        spec.rise_m = f;
        spec.span_m = 2.0 * std::sqrt(std::max(0.0, r * r - (r - f) * (r - f)));
    } else {
        spec.span_m = *span;
        spec.rise_m = rise.value_or(0.5 * *span);
        if (spec.rise_m > 0.5 * spec.span_m)
            t.fail("rise", fmt::format("must be <= span / 2 = {} m (a semicircle at most), got {}", 0.5 * spec.span_m, spec.rise_m));
    }
    if (spec.rise_m < 1e-3 * spec.span_m)
        t.fail("rise", fmt::format("must be at least span / 1000 = {:g} m (a flatter arch is a lintel), got {}", 1e-3 * spec.span_m,
                                   spec.rise_m));
    if (!(spec.span_m < 1e4)) t.fail(radius ? "radius" : "span", fmt::format("the span must be < 10 km, got {} m", spec.span_m));
    spec.ring_thickness_m = t.positive("ring_thickness");
    const double r = scenes::arch_radius_m(spec.span_m, spec.rise_m);
    if (spec.ring_thickness_m >= 2.0 * r)
        t.fail("ring_thickness", fmt::format("must be < 2 x the centre line's radius = {:g} m, got {}", 2.0 * r, spec.ring_thickness_m));
    spec.voussoirs = static_cast<int>(t.whole_number("voussoirs", 3, 100000));
    spec.abutment_height_m = t.optional_positive("abutment_height").value_or(spec.ring_thickness_m);
    const BodyKind abutments = t.choice("abutments", {"fixed", "driven"}, "fixed") == "fixed" ? BodyKind::fixed : BodyKind::driven;
    return scenes::arch_bodies(scenes::masonry_arch(spec), style, abutments);
}

// group: the assembly's bond group, used when it has bonded = true (model.hpp, BodyDef).
std::vector<BodyDef> read_assembly(TableReader t, std::uint32_t group) {
    const std::string type = t.choice("type", {"column", "wall", "rock_mass", "voronoi", "arch"}, "");
    const scenes::BlockStyle style = read_style(t);
    std::vector<scenes::Polygon> polygons;
    std::vector<BodyDef> bodies;
    try {
        if (type == "column") polygons = read_column(t);
        if (type == "wall") polygons = read_wall(t);
        if (type == "rock_mass") polygons = read_rock_mass(t).polygons;
        if (type == "voronoi") polygons = read_voronoi(t).polygons;
        if (type == "arch") bodies = read_arch(t, style);
    } catch (const std::invalid_argument& e) {
        t.fail("", e.what());  // a generator's own check (region outline, spread range, ...)
    }
    if (type != "arch") bodies = scenes::as_bodies(polygons, style);
    for (BodyDef& b : bodies) b.assembly = style.name_prefix;  // the collapse summary's group
    // Bonded: its blocks to each other and to its own fixed or driven zone blocks, where they
    // touch at the start (contact/bonded_pairs.hpp).
    if (t.boolean_or("bonded", false))
        for (BodyDef& b : bodies) b.bond_group = group;
    // Boundary blocks: those whose centroid lies in a zone move with the table (or stay fixed).
    for (const char* key : {"driven_zone", "fixed_zone"})
        if (t.has(key) && scenes::set_kind_inside(bodies, t.vec2_list(key), key[0] == 'd' ? BodyKind::driven : BodyKind::fixed) == 0)
            t.fail(key, "no block has its centroid in this zone");
    t.reject_unknown_keys();
    if (bodies.empty()) t.fail("", "the assembly has no blocks (check its size and region)");
    return bodies;
}

}  // namespace

void check_block_budget(TableReader& t, const std::string& key, double blocks, const std::string& how,
                        double bytes_per_block) {
    const double bytes = blocks * bytes_per_block;
    const double memory = static_cast<double>(physical_memory_bytes());
    const double memory_blocks = memory > 0.0 ? memory / bytes_per_block : max_assembly_blocks;
    const double limit = std::min(max_assembly_blocks, memory_blocks);
    if (blocks <= limit) return;
    t.fail(key, fmt::format("the assembly would have about {:.3g} blocks ({}), needing about {} at {} a block; the limit is {:.3g} "
                            "blocks ({})",
                            blocks, how, format_bytes(bytes), format_bytes(bytes_per_block), limit,
                            limit == max_assembly_blocks ? "the most a run may have"
                                                         : fmt::format("this machine's {} of memory", format_bytes(memory))));
}


SettlingSettings read_settling(TableReader t) {
    SettlingSettings s;
    s.kinetic_ratio = t.optional_positive("kinetic_ratio").value_or(s.kinetic_ratio);
    s.window_s = t.optional_positive("window").value_or(s.window_s);
    s.max_time_s = t.optional_positive("max_time").value_or(s.max_time_s);
    // Settled means quiet over a whole window: one longer than the time allowed never settles,
    // which the settling stage found only once it had run that long.
    if (s.window_s > s.max_time_s)
        t.fail(t.has("window") ? "window" : "max_time",
               fmt::format("the window, {:g} s, is longer than max_time, {:g} s: the settling could never end settled", s.window_s,
                           s.max_time_s));
    s.friction = t.choice("friction", {"held", "actual"}, "held") == "held" ? SettlingFriction::held : SettlingFriction::actual;
    t.reject_unknown_keys();
    return s;
}

void check_assembly_name(const TableReader& t, const std::string& name, std::set<std::string>& seen) {
    if (name == "all")
        t.fail("name", "'all' names the collapse summary of every block (summary.json, collapse); choose another name");
    if (!seen.insert(name).second)
        t.fail("name", fmt::format("another assembly is named '{}' (each assembly is its own collapse group); choose another name",
                                   name));
}

void read_assemblies(TableReader& top, Model& model) {
    std::set<std::string> assemblies;
    std::set<std::string> names;
    for (const BodyDef& b : model.bodies) names.insert(b.name);
    // Bond groups: 1 for the [[bodies]] with bonded = true, 2, 3, ... for the assemblies.
    std::uint32_t group = 1;
    for (const TableReader& t : top.table_array("assemblies")) {
        std::vector<BodyDef> bodies = read_assembly(t, ++group);
        check_assembly_name(t, bodies.front().assembly, assemblies);  // (an assembly with no block is refused)
        for (BodyDef& b : bodies) {
            if (!names.insert(b.name).second)
                t.fail("name", fmt::format("the generated block '{}' has the name of another body; choose another name", b.name));
            model.bodies.push_back(std::move(b));
        }
    }
    if (auto settling = top.optional_table("settling")) model.settling = read_settling(*settling);
}

}  // namespace blockdem
