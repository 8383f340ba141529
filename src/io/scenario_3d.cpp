#include "io/scenario_3d.hpp"

#include <cmath>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "geometry/polygon.hpp"
#include "io/assembly_3d_keys.hpp"
#include "io/assembly_keys.hpp"
#include "io/motion_sampling.hpp"
#include "io/outcome_keys.hpp"
#include "io/overrides.hpp"
#include "io/record_motion_keys.hpp"
#include "io/scenario.hpp"
#include "io/scenario_keys.hpp"
#include "io/vec3_keys.hpp"
#include "scenes/brick_wall_3d.hpp"
#include "world/settling_3d.hpp"
#include "world/simulation_error.hpp"
#include "world/world.hpp"
#include "world/world_3d_start.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;
// A prism's sides: the hull search is O(n^4) in the vertices (docs/3d.md): 64 sides take 25 ms,
// 128 about 0.4 s a body.
constexpr std::int64_t max_sides = 128;

// [simulation] domain = [[x_min, y_min, z_min], [x_max, y_max, z_max]] (m): the model's extent
// (world/model_domain_3d.hpp); nullopt derives it.
std::optional<Aabb3d> read_domain_3d(TableReader& t) {
    if (!t.has("domain")) return std::nullopt;
    const std::vector<Vec3> corners = vec3_list(t, "domain");
    if (corners.size() != 2)
        t.fail("domain", fmt::format("must be two corners [[x_min, y_min, z_min], [x_max, y_max, z_max]] in m, got {} "
                                     "points", corners.size()));
    const Aabb3d box{corners[0], corners[1]};
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
        t.fail("domain", fmt::format("the first corner must be below the second in x, y and z, got [[{:g}, {:g}, {:g}], "
                                     "[{:g}, {:g}, {:g}]]", box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z));
    return box;
}

SimulationSettings read_settings_3d(TableReader t, std::optional<Aabb3d>& domain) {
    SimulationSettings s;
    read_run_keys(t, s);
    s.gravity_m_s2 = t.number_or("gravity", s.gravity_m_s2);
    if (s.gravity_m_s2 < 0.0) t.fail("gravity", "is a magnitude [m/s^2] acting in -z and must be >= 0");
    domain = read_domain_3d(t);
    t.allow({"initial_state"});  // a state file: read by load_scenario_3d (io, not physics)
    t.reject_unknown_keys();
    return s;
}

ContactParameters read_contact_3d(TableReader t) {
    ContactParameters defaults;
    defaults.h_s = 1.0;  // the paper's recommendation, as in 2-D
    const ContactParameters p = read_contact_parameters(t, defaults, true, true);
    if (p.stiffness != StiffnessBasis::per_point)
        t.fail("stiffness", "3-D contacts take kn and ks per contact point [N/m]: per-length stiffness is 2-D only");
    t.reject_unknown_keys();
    return p;
}

// The turn of a body: rotation = [rx, ry, rz] a rotation vector [rad] (axis times angle), or
// rotation_deg the same in degrees.
Quaternion read_turn(TableReader& t) {
    const auto rad = optional_vec3(t, "rotation");
    const auto deg = optional_vec3(t, "rotation_deg");
    if (rad && deg) t.fail("rotation_deg", "give either rotation [rad] or rotation_deg [deg], not both");
    if (deg) return from_rotation_vector((pi / 180.0) * *deg);
    return rad ? from_rotation_vector(*rad) : Quaternion{};
}

// A regular polygon of `sides` corners on a circle of radius_m, the first on +x.
std::vector<Vec2> regular_polygon(int sides, double radius_m) {
    std::vector<Vec2> p;
    for (int k = 0; k < sides; ++k)
        p.push_back({radius_m * std::cos(2.0 * pi * k / sides), radius_m * std::sin(2.0 * pi * k / sides)});
    return p;
}

// A prism's vertices with its centroid at the origin: the polygon's centroid on the axis, half
// the height below and above.
std::vector<Vec3> centered_prism(std::vector<Vec2> polygon_m, double height_m) {
    const Vec2 c = polygon_properties(counter_clockwise(polygon_m)).centroid_m;
    for (Vec2& v : polygon_m) v = v - c;
    std::vector<Vec3> vertices = prism_vertices(polygon_m, height_m);
    for (Vec3& v : vertices) v.z -= 0.5 * height_m;
    return vertices;
}

struct BodyDef3d {
    std::string name;
    std::string key;               ///< the table it came from (bodies.NAME, assemblies.NAME), for messages
    std::string assembly;          ///< the assembly's name (its collapse group); "" for [[bodies]]
    BodyKind3d kind = BodyKind3d::dynamic;
    std::vector<Vec3> vertices_m;  ///< [m] world frame at t = 0
    std::vector<std::vector<std::size_t>> faces;  ///< as listed (polyhedron `faces`); empty: from the hull
    double density_kg_m3 = 0.0;    ///< [kg/m^3]
    Vec3 velocity_m_s;             ///< [m/s]
    Vec3 angular_velocity_rad_s;   ///< [rad/s] world frame
};

// faces = [[0, 2, 1], ...]: vertex indices counter-clockwise seen from outside, each checked
// against the hull by make_rigid_body_3d (an inverted or missing face is refused by number).
std::vector<std::vector<std::size_t>> read_faces(TableReader& t, std::size_t vertex_count) {
    const toml::array* rows = t.raw().get_as<toml::array>("faces");
    if (!rows) t.fail("faces", "must be a list of faces, each a list of vertex indices");
    std::vector<std::vector<std::size_t>> faces;
    for (std::size_t i = 0; i < rows->size(); ++i) {
        const toml::array* row = (*rows)[i].as_array();
        if (!row || row->size() < 3) t.fail("faces", fmt::format("face {} must list at least three vertex indices", i));
        std::vector<std::size_t> face;
        for (const toml::node& index : *row) {
            const auto k = index.value<std::int64_t>();
            if (!k || *k < 0 || static_cast<std::size_t>(*k) >= vertex_count)
                t.fail("faces", fmt::format("face {}: vertex indices must be whole numbers from 0 to {}", i, vertex_count - 1));
            face.push_back(static_cast<std::size_t>(*k));
        }
        faces.push_back(std::move(face));
    }
    return faces;
}

BodyKind3d read_kind(TableReader& t) {
    const std::string kind = t.choice("kind", {"dynamic", "fixed", "driven"}, "dynamic");
    return kind == "dynamic" ? BodyKind3d::dynamic : kind == "fixed" ? BodyKind3d::fixed : BodyKind3d::driven;
}

// density [kg/m^3]: needed by a dynamic body; a fixed or driven one's mass enters nothing, so
// it may be left out.
double read_density(TableReader& t, const std::string& name, BodyKind3d kind) {
    const auto density = t.optional_positive("density");
    if (!density && kind == BodyKind3d::dynamic) t.fail("", fmt::format("body '{}' needs 'density' [kg/m^3]", name));
    return density.value_or(1000.0);
}

BodyDef3d read_body_3d(TableReader t) {
    BodyDef3d b;
    b.name = read_body_name(t);
    b.key = t.path();
    b.kind = read_kind(t);
    const std::string shape = t.choice("shape", {"box", "prism", "polyhedron"}, "");
    std::vector<Vec3> local_m;  // about the point `position` places
    if (shape == "box") {
        const Vec3 size = vec3(t, "size", " ([x, y, z] edge lengths in m)");
        if (!(size.x > 0.0 && size.y > 0.0 && size.z > 0.0)) t.fail("size", "edge lengths must be > 0");
        local_m = box_vertices(size, {});
    } else if (shape == "prism") {
        const double height = t.positive("height");
        if (t.has("polygon")) {
            if (t.has("sides") || t.has("radius")) t.fail("polygon", "give either polygon or sides and radius, not both");
            const std::vector<Vec2> polygon = t.vec2_list("polygon");
            // Checked as the 2-D polygon it is: the hull of its extrusion named a vertex of the
            // centred prism the user never wrote.
            if (const auto problem = convexity_problem(counter_clockwise(polygon)))
                t.fail("polygon", fmt::format("is not a convex polygon: {}", *problem));
            local_m = centered_prism(polygon, height);
        } else {
            const auto sides = t.whole_number("sides", 3, max_sides);
            local_m = centered_prism(regular_polygon(static_cast<int>(sides), t.positive("radius")), height);
        }
    } else {
        local_m = vec3_list(t, "vertices");
        if (t.has("faces")) b.faces = read_faces(t, local_m.size());
    }
    const Quaternion turn = read_turn(t);
    const Vec3 position = shape == "polyhedron" ? optional_vec3(t, "position").value_or(Vec3{})
                                                : vec3(t, "position", " ([x, y, z] of the centroid in m)");
    for (const Vec3& v : local_m) b.vertices_m.push_back(position + rotate(turn, v));
    b.density_kg_m3 = read_density(t, b.name, b.kind);
    b.velocity_m_s = optional_vec3(t, "velocity").value_or(Vec3{});
    b.angular_velocity_rad_s = optional_vec3(t, "angular_velocity").value_or(Vec3{});
    t.reject_unknown_keys();
    return b;
}

// [[assemblies]] type = "drum_column": `drums` prisms of `sides` corners, radius and height
// each, stacked touching from `base` (the centre of the lowest face) up; named NAME_1 (lowest)
// to NAME_n.
std::vector<BodyDef3d> read_drum_column(TableReader& t, const std::string& name) {
    const auto drums = t.whole_number("drums", 1, 10000);
    check_block_budget(t, "drums", static_cast<double>(drums), fmt::format("drums = {}", drums), bytes_per_block_3d);
    const auto sides = t.whole_number_or("sides", 32, 3, max_sides);
    const double radius = t.positive("radius");
    const double height = t.positive("height");
    const Vec3 base = vec3(t, "base", " ([x, y, z] of the centre of the column's lowest face in m)");
    const BodyKind3d kind = read_kind(t);
    const double density = read_density(t, name, kind);
    const std::vector<Vec3> drum = centered_prism(regular_polygon(static_cast<int>(sides), radius), height);
    std::vector<BodyDef3d> bodies;
    for (std::int64_t k = 0; k < drums; ++k) {
        BodyDef3d b;
        b.name = fmt::format("{}_{}", name, k + 1);
        b.kind = kind;
        b.density_kg_m3 = density;
        const Vec3 centre = base + Vec3{0.0, 0.0, (static_cast<double>(k) + 0.5) * height};
        for (const Vec3& v : drum) b.vertices_m.push_back(centre + v);
        bodies.push_back(std::move(b));
    }
    return bodies;
}

// [[assemblies]] type = "brick_wall": `courses` of `bricks_per_course` boxes of size `brick` in
// `wythes` side by side, running bond (scenes/brick_wall_3d.hpp), from `origin` (the wall's
// lowest, first corner: bricks run along +x, wythes along +y, courses up); named
// NAME_<course>_<wythe>_<index>, from 0.
std::vector<BodyDef3d> read_brick_wall(TableReader& t, const std::string& name) {
    const auto courses = t.whole_number("courses", 1, 100000);
    const auto per_course = t.whole_number("bricks_per_course", 1, 100000);
    // Running bond's odd courses hold one brick fewer: with one a course they would be empty and
    // every course above them would float. (A single stack of bricks is not a bond: [[bodies]]
    // boxes build it.)
    if (per_course < 2 && courses > 1)
        t.fail("bricks_per_course",
               fmt::format("is 1 with {} courses: in running bond the odd courses, shifted half a brick, hold one brick "
                           "fewer, so they would be empty and the bricks above would float; give at least 2 (or courses = 1)",
                           courses));
    const auto wythes = t.whole_number_or("wythes", 1, 1, 1000);
    const Vec3 brick = vec3(t, "brick", " ([length, thickness, height] of a brick in m)");
    if (!(brick.x > 0.0 && brick.y > 0.0 && brick.z > 0.0)) t.fail("brick", "edge lengths must be > 0");
    check_block_budget(t, "courses", static_cast<double>(courses * per_course * wythes),
                       fmt::format("courses x bricks_per_course x wythes = {} x {} x {}", courses, per_course, wythes),
                       bytes_per_block_3d);
    const Vec3 origin = vec3(t, "origin", " ([x, y, z] of the wall's lowest first corner in m)");
    const BodyKind3d kind = read_kind(t);
    const double density = read_density(t, name, kind);
    std::vector<BodyDef3d> bodies;
    for (const scenes::BrickPlacement3d& p : scenes::running_bond_3d(static_cast<int>(courses), static_cast<int>(per_course),
                                                                      static_cast<int>(wythes), brick)) {
        BodyDef3d b;
        b.name = fmt::format("{}_{}_{}_{}", name, p.course, p.wythe, p.index);
        b.kind = kind;
        b.density_kg_m3 = density;
        b.vertices_m = box_vertices(brick, origin + p.centre_m);
        bodies.push_back(std::move(b));
    }
    return bodies;
}

// The generated assemblies (io/assembly_3d_keys.hpp) as body definitions; their note kept.
std::vector<BodyDef3d> generated_bodies(GeneratedAssembly3d assembly, std::vector<std::string>& notes) {
    std::vector<BodyDef3d> bodies;
    for (GeneratedBody3d& g : assembly.bodies) {
        BodyDef3d b;
        b.name = std::move(g.name);
        b.kind = g.kind;
        b.vertices_m = std::move(g.vertices_m);
        b.density_kg_m3 = g.density_kg_m3;
        bodies.push_back(std::move(b));
    }
    notes.push_back(std::move(assembly.note));
    return bodies;
}

std::vector<BodyDef3d> read_assembly_3d(TableReader t, std::vector<std::string>& notes) {
    const std::string name = read_body_name(t);  // (it begins every block's name)
    const std::string type = t.choice("type", {"drum_column", "brick_wall", "rock_mass", "random_packing"}, "");
    std::vector<BodyDef3d> bodies = type == "drum_column"      ? read_drum_column(t, name)
                                    : type == "brick_wall"     ? read_brick_wall(t, name)
                                    : type == "rock_mass"      ? generated_bodies(read_rock_mass_3d(t, name), notes)
                                                               : generated_bodies(read_random_packing_3d(t, name), notes);
    for (BodyDef3d& b : bodies) {
        b.key = t.path();
        b.assembly = name;
    }
    t.reject_unknown_keys();
    return bodies;
}

// [table_motion.record]: one file holding two horizontal components and a vertical one, read as
// [table_motion.horizontal] and [table_motion.vertical] read a record (docs/records.md), one
// component each: `components = [first horizontal, second horizontal, vertical]` (column names
// or numbers as `component` takes them). A file without the third is refused by the record
// reader, naming the file.
TableMotion3d read_record_3d(TableReader& t, const std::filesystem::path& scenario_dir) {
    t.has("components");
    const toml::array* names = t.raw().get_as<toml::array>("components");
    if (!names || names->size() != 3)
        t.fail("components", "must list three components: [first horizontal, second horizontal, vertical], e.g. "
                             "[\"NS\", \"EW\", \"UD\"]");
    TableMotion3d m;
    ComponentMotion* targets[3] = {&m.x, &m.y, &m.z};
    const char* roles[3] = {"horizontal", "horizontal", "vertical"};
    for (std::size_t k = 0; k < 3; ++k) {
        toml::table one = t.raw();
        one.erase("components");
        if (auto text = (*names)[k].value<std::string>())
            one.insert_or_assign("component", *text);
        else if (auto number = (*names)[k].value<std::int64_t>())
            one.insert_or_assign("component", *number);
        else
            t.fail("components", fmt::format("entry {} must be a column name or number", k + 1));
        // (The path ends in the role, so that the record reader's check of a vertical component
        // where a horizontal one is asked applies as in 2-D.)
        TableReader keys(one, t.file(), fmt::format("{}.{}", t.path(), roles[k]));
        *targets[k] = read_record_motion(keys, scenario_dir);
    }
    return m;
}

// A series' samples turned: the component along `along` of the pair (x, y) at the azimuth.
// Both are series on the same samples (what a record's components are), or at rest.
AccelerationSeries turned_series(const AccelerationSeries& x, const AccelerationSeries& y, double cos_a, double sin_a,
                                 bool second) {
    std::vector<double> a(x.time_s.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        a[i] = second ? sin_a * x.acceleration_m_s2[i] + cos_a * y.acceleration_m_s2[i]
                      : cos_a * x.acceleration_m_s2[i] - sin_a * y.acceleration_m_s2[i];
    return make_acceleration_series(x.time_s, std::move(a), x.source + (x.source == y.source ? "" : " + " + y.source));
}

// azimuth_deg: the first horizontal component acts along the direction azimuth_deg from +x
// toward +y, the second 90 degrees further (a record's NS and EW laid on the model's axes).
// Sampled series only (records, csv, series, synthetic), on the same samples.
void turn_horizontal(TableReader& t, TableMotion3d& m) {
    const auto azimuth = t.optional_number("azimuth_deg");
    if (!azimuth || *azimuth == 0.0) return;
    const auto* x = std::get_if<AccelerationSeries>(&m.x);
    const auto* y = std::get_if<AccelerationSeries>(&m.y);
    AccelerationSeries zeros;
    if (x && std::holds_alternative<RestMotion>(m.y)) zeros = *x;
    if (y && std::holds_alternative<RestMotion>(m.x)) zeros = *y;
    for (double& v : zeros.acceleration_m_s2) v = 0.0;
    if (!x && !zeros.time_s.empty()) x = &zeros;
    if (!y && !zeros.time_s.empty()) y = &zeros;
    if (!x || !y)
        t.fail("azimuth_deg", "turns sampled motions (records, csv, series, synthetic) only; turn an analytic motion "
                              "by giving its x and y components");
    if (x->time_s != y->time_s)
        t.fail("azimuth_deg", fmt::format("the two horizontal components ({} and {}) are not sampled at the same times; "
                                          "give two components of one record",
                                          x->source, y->source));
    const double c = std::cos(*azimuth * pi / 180.0), s = std::sin(*azimuth * pi / 180.0);
    AccelerationSeries first = turned_series(*x, *y, c, s, false);
    AccelerationSeries second = turned_series(*x, *y, c, s, true);
    m.x = std::move(first);
    m.y = std::move(second);
}

// [table_motion]: x, y (horizontal) and z (vertical) tables, each a 2-D component's keys; or a
// record with three components ([table_motion.record]); azimuth_deg turns the horizontal pair.
TableMotion3d read_table_motion_3d(TableReader t, const std::filesystem::path& scenario_dir) {
    TableMotion3d m;
    if (auto record = t.optional_table("record")) {
        for (const char* key : {"x", "y", "z"})
            if (t.has(key)) t.fail(key, "give either [table_motion.record] (three components of one record) or x, y, z");
        m = read_record_3d(*record, scenario_dir);
    } else {
        if (auto x = t.optional_table("x")) m.x = read_component(*x, scenario_dir);
        if (auto y = t.optional_table("y")) m.y = read_component(*y, scenario_dir);
        if (auto z = t.optional_table("z")) m.z = read_component(*z, scenario_dir);
    }
    turn_horizontal(t, m);
    t.reject_unknown_keys();
    return m;
}

InputError model_error(const std::filesystem::path& file, const std::string& key, const std::string& what) {
    return InputError({file.string(), key, 0, 0}, what);
}

World3d build_world_3d(TableReader& top, const std::filesystem::path& file, const std::filesystem::path& scenario_dir,
                       std::vector<std::string>& notes) {
    World3d w;
    std::vector<BodyDef3d> defs;
    for (TableReader bt : top.table_array("bodies")) defs.push_back(read_body_3d(bt));
    std::set<std::string> assemblies;
    for (TableReader at : top.table_array("assemblies")) {
        std::vector<BodyDef3d> bodies = read_assembly_3d(at, notes);
        if (!bodies.empty()) check_assembly_name(at, bodies.front().assembly, assemblies);
        for (BodyDef3d& b : bodies) defs.push_back(std::move(b));
    }
    if (defs.empty()) top.fail("", "the scenario has no [[bodies]] or [[assemblies]]");
    std::set<std::string> names;
    for (const BodyDef3d& d : defs) {
        if (!names.insert(d.name).second) top.fail("bodies", fmt::format("two bodies are named '{}'", d.name));
        try {
            RigidBody3d b = d.faces.empty() ? make_rigid_body_3d(d.name, d.vertices_m, d.density_kg_m3)
                                            : make_rigid_body_3d(d.name, d.vertices_m, d.faces, d.density_kg_m3);
            set_initial_velocity(b, d.velocity_m_s, d.angular_velocity_rad_s);
            add_body(w, std::move(b), d.kind, d.assembly);
        } catch (const ModelError& e) {
            throw model_error(file, d.key, e.what());
        }
    }
    w.contact = read_contact_3d(top.table("contact"));
    if (auto motion = top.optional_table("table_motion")) w.table = read_table_motion_3d(*motion, scenario_dir);
    return w;
}

}  // namespace

int scenario_dimension(const toml::table& root, const std::string& file) {
    const toml::node* d = root.get("dimension");
    if (!d) return 2;
    const auto value = d->value<double>();
    if (!value || (*value != 2.0 && *value != 3.0)) {
        const auto& where = d->source().begin;
        throw InputError({file, "dimension", static_cast<int>(where.line), static_cast<int>(where.column)},
                         "must be 2 or 3");
    }
    return static_cast<int>(*value);
}

LoadedScenario3d load_scenario_3d(const std::filesystem::path& file, const std::vector<std::string>& overrides, bool settle,
                                  const std::atomic<bool>* stop_requested) {
    return load_scenario_3d(load_toml_file(file), file, overrides, settle, stop_requested);
}

LoadedScenario3d load_scenario_3d(toml::table root, const std::filesystem::path& file,
                                  const std::vector<std::string>& overrides, bool settle,
                                  const std::atomic<bool>* stop_requested) {
    LoadedScenario3d s;
    s.file = file;
    s.root = std::move(root);
    apply_overrides_to_scenario(s.root, overrides, file);
    TableReader top(s.root, file.string(), "");
    top.number("dimension");
    std::optional<Aabb3d> domain;
    const SimulationSettings settings = read_settings_3d(top.table("simulation"), domain);
    s.duration_s = settings.duration_s;
    s.output_interval_s = settings.output_interval_s;
    s.max_energy_error = settings.max_energy_error;
    s.max_overlap_ratio = settings.max_overlap_ratio;
    s.world = build_world_3d(top, file, file.parent_path(), s.assembly_notes);
    const auto count_kind = [&](BodyKind3d kind) {
        return static_cast<std::size_t>(std::count(s.world.kinds.begin(), s.world.kinds.end(), kind));
    };
    check_some_body_moves(file.string(), count_kind(BodyKind3d::dynamic), count_kind(BodyKind3d::fixed),
                          count_kind(BodyKind3d::driven));
    s.world.gravity_m_s2 = settings.gravity_m_s2;
    s.world.duration_s = settings.duration_s;
    s.world.output_interval_s = settings.output_interval_s;
    if (auto output = top.optional_table("output")) s.output = read_output_settings(*output);
    if (auto outcomes = top.optional_table("outcomes")) s.outcomes = read_outcome_thresholds(*outcomes);
    if (auto settling = top.optional_table("settling")) s.settling = read_settling(*settling);
    TableReader simulation = top.table("simulation");
    if (auto state = simulation.optional_string("initial_state")) {
        if (state->empty()) simulation.fail("initial_state", "is empty: give a state file (.h5)");
        if (s.settling)
            simulation.fail("initial_state", "starts from a state that is already settled: remove [settling] (or "
                                              "initial_state)");
        s.initial_state = std::filesystem::path(*state).is_absolute() ? std::filesystem::path(*state)
                                                                      : file.parent_path() / *state;
    }
    read_scenario_labels(top);
    top.reject_unknown_keys();
    try {
        check_no_initial_overlap_3d(s.world);
        s.start = set_time_step_3d(s.world, settings.dt_s, settings.dt_safety, s.output_interval_s);
        s.critical_dt_s = s.start.highest_mode.dt_s;
    } catch (const ModelError& e) {
        throw model_error(file, settings.dt_s && std::string(e.what()).starts_with("time step") ? "simulation.dt" : "",
                          e.what());
    }
    if (auto motion = top.optional_table("table_motion")) {  // dt is known from here on
        check_motion_sampling(*motion, "x", s.world.table.x, s.world.dt_s);
        check_motion_sampling(*motion, "y", s.world.table.y, s.world.dt_s);
        check_motion_sampling(*motion, "z", s.world.table.z, s.world.dt_s);
    }
    try {
        init_model_domain_3d(s.world, domain);
    } catch (const ModelError& e) {
        throw model_error(file, "simulation.domain", e.what());
    }
    if (settle && s.settling) {
        const SettlingReport report = settle_3d(s.world, *s.settling, stop_requested);
        if (report.stopped) throw SettlingStopped(report);
        // A run that started and could not settle failed (exit 3), it is not bad input.
        if (!report.settled) throw SimulationError(settling_failure(report, *s.settling));
        s.settled = settling_record(report, *s.settling);
    }
    return s;
}

}  // namespace blockdem
