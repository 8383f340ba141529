#include "io/state_file_3d.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "io/external_loads_state.hpp"
#include "io/input_error.hpp"
#include "io/run_restart.hpp"

namespace blockdem {
namespace {

std::vector<double> flat(const std::vector<Vec3>& v) {
    std::vector<double> out;
    out.reserve(3 * v.size());
    for (Vec3 p : v) out.insert(out.end(), {p.x, p.y, p.z});
    return out;
}

std::vector<Vec3> vec3s(const StateGroup& g, const std::string& name, std::size_t n) {
    const std::vector<double> v = g.doubles(name, static_cast<std::int64_t>(3 * n), 3);
    std::vector<Vec3> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    return out;
}

template <class T, class Item, class Field>
std::vector<T> column(const std::vector<Item>& items, Field field) {
    std::vector<T> out;
    out.reserve(items.size());
    for (const Item& item : items) out.push_back(field(item));
    return out;
}

void write_bodies(StateGroup g, const World3d& w) {
    const auto& b = w.bodies;
    g.write("name", column<std::string>(b, [](const RigidBody3d& x) { return x.name; }));
    g.write("kind", column<std::uint8_t>(w.kinds, [](BodyKind3d k) { return static_cast<std::uint8_t>(k); }));
    g.write("vertex_count", column<std::uint32_t>(b, [](const RigidBody3d& x) { return std::uint32_t(x.shape.vertices_m.size()); }));
    g.write("position_m", flat(column<Vec3>(b, [](const RigidBody3d& x) { return x.position_m; })), 3);
    std::vector<double> q;
    for (const RigidBody3d& x : b) q.insert(q.end(), {x.orientation.w, x.orientation.x, x.orientation.y, x.orientation.z});
    g.write("orientation", q, 4);
    g.write("velocity_m_s", flat(column<Vec3>(b, [](const RigidBody3d& x) { return x.velocity_m_s; })), 3);
    g.write("angular_momentum_kg_m2_s", flat(column<Vec3>(b, [](const RigidBody3d& x) { return x.angular_momentum_kg_m2_s; })), 3);
    g.write("angular_velocity_body_rad_s",
            flat(column<Vec3>(b, [](const RigidBody3d& x) { return x.angular_velocity_body_rad_s; })), 3);
    g.write("velocity_at_t_m_s", flat(column<Vec3>(b, [](const RigidBody3d& x) { return x.velocity_at_t_m_s; })), 3);
    g.write("angular_velocity_at_t_rad_s",
            flat(column<Vec3>(b, [](const RigidBody3d& x) { return x.angular_velocity_at_t_rad_s; })), 3);
    // To recognise the bodies (read_bodies): their shapes and mass properties.
    std::vector<Vec3> local;
    for (const RigidBody3d& x : b) local.insert(local.end(), x.shape.vertices_m.begin(), x.shape.vertices_m.end());
    g.write("local_vertices_m", flat(local), 3);
    g.write("mass_kg", column<double>(b, [](const RigidBody3d& x) { return x.mass_kg; }));
    g.write("principal_moments_kg_m2", flat(column<Vec3>(b, [](const RigidBody3d& x) { return x.principal_moments_kg_m2; })), 3);
}

void write_contacts(StateGroup g, const World3d& w) {
    const std::vector<ContactPoint3d>& c = w.contacts;
    g.write("body_a", column<std::uint32_t>(c, [](const ContactPoint3d& p) { return p.key.body_a; }));
    g.write("body_b", column<std::uint32_t>(c, [](const ContactPoint3d& p) { return p.key.body_b; }));
    g.write("feature_a", column<std::uint32_t>(c, [](const ContactPoint3d& p) { return p.key.feature_a; }));
    g.write("feature_b", column<std::uint32_t>(c, [](const ContactPoint3d& p) { return p.key.feature_b; }));
    g.write("point_m", flat(column<Vec3>(c, [](const ContactPoint3d& p) { return p.point_m; })), 3);
    g.write("normal", flat(column<Vec3>(c, [](const ContactPoint3d& p) { return p.normal; })), 3);
    g.write("overlap_m", column<double>(c, [](const ContactPoint3d& p) { return p.overlap_m; }));
    g.write("stiffness_share", column<double>(c, [](const ContactPoint3d& p) { return p.stiffness_share; }));
    // Made from the table (the point no longer holds it) and still written: a build from before
    // the fifteenth session requires the column to read the file. This one does not read it.
    g.write("dashpot_mass_kg", point_dashpot_masses_kg(w, c));
    g.write("normal_dashpot_n", column<double>(c, [](const ContactPoint3d& p) { return p.normal_dashpot_n; }));
    g.write("shear_spring_n", flat(column<Vec3>(c, [](const ContactPoint3d& p) { return p.shear.spring_n; })), 3);
    g.write("shear_dashpot_n", flat(column<Vec3>(c, [](const ContactPoint3d& p) { return p.shear.dashpot_n; })), 3);
    g.write("sliding", column<std::uint8_t>(c, [](const ContactPoint3d& p) { return std::uint8_t(p.sliding); }));
    g.write("force_n", flat(column<Vec3>(c, [](const ContactPoint3d& p) { return p.force_n; })), 3);
}

void write_stability(StateGroup g, const StabilityWatch3d& s) {
    g.set("start_bound_s", s.start_bound_s);
    g.set("limit_ratio", s.limit_ratio);
    g.set("ratio_bound_s", s.ratio_bound_s);
    g.set("estimates", s.estimates);
    g.set("least_limit_s", s.least_limit_s);
    g.set("least_limit_body", s.least_limit_body);
    g.set("least_limit_time_s", s.least_limit_time_s);
    g.set("first_exceeded_s", s.first_exceeded_s);
    g.set("exceeded_body", s.exceeded_body);
    g.set("max_overlap_ratio", s.max_overlap_ratio);
    g.set("max_overlap_m", s.max_overlap_m);
    g.set("max_overlap_time_s", s.max_overlap_time_s);
    g.set("max_overlap_body_a", std::int64_t{s.max_overlap_body_a});
    g.set("max_overlap_body_b", std::int64_t{s.max_overlap_body_b});
}

[[noreturn]] void refuse(const StateFile& file, const std::filesystem::path& scenario, const std::string& why) {
    throw InputError({file.path().string(), "", 0, 0},
                     fmt::format("the state does not belong to scenario {}: {}", scenario.string(), why));
}

// The same corners in each body's frame (exactly: both come from the same numbers). Files
// written before the shapes were saved pass.
void check_shapes(const StateFile& file, const std::filesystem::path& scenario, const StateGroup& g, const World3d& w) {
    if (!g.has("local_vertices_m")) return;
    std::size_t corners = 0;
    for (const RigidBody3d& b : w.bodies) corners += b.shape.vertices_m.size();
    const std::vector<Vec3> local = vec3s(g, "local_vertices_m", corners);
    std::size_t k = 0;
    for (const RigidBody3d& b : w.bodies)
        for (std::size_t v = 0; v < b.shape.vertices_m.size(); ++v, ++k)
            if (local[k].x != b.shape.vertices_m[v].x || local[k].y != b.shape.vertices_m[v].y ||
                local[k].z != b.shape.vertices_m[v].z)
                refuse(file, scenario, fmt::format("body '{}' has another shape in the state than in the scenario "
                                                   "(vertex {})", b.name, v + 1));
}

// A restart's bodies must keep their mass properties (io/run_restart.hpp: restart_body_change).
void check_masses(const StateFile& file, const std::filesystem::path& scenario, const StateGroup& g, const World3d& w) {
    if (!g.has("mass_kg") || !g.has("principal_moments_kg_m2")) return;
    const std::size_t n = w.bodies.size();
    const std::vector<double> mass = g.doubles("mass_kg", static_cast<std::int64_t>(n));
    const std::vector<Vec3> moments = vec3s(g, "principal_moments_kg_m2", n);
    const auto differs = [](double a, double b) { return std::abs(a - b) > 1e-12 * std::max(std::abs(a), std::abs(b)); };
    for (std::size_t i = 0; i < n; ++i) {
        const RigidBody3d& b = w.bodies[i];
        if (w.kinds[i] != BodyKind3d::dynamic) continue;
        std::string why;
        if (differs(mass[i], b.mass_kg))
            why = fmt::format("body '{}' has mass {:g} kg in the state but {:g} kg in the scenario (its density or size "
                              "changed)", b.name, mass[i], b.mass_kg);
        else if (differs(moments[i].x, b.principal_moments_kg_m2.x) || differs(moments[i].y, b.principal_moments_kg_m2.y) ||
                 differs(moments[i].z, b.principal_moments_kg_m2.z))
            why = fmt::format("body '{}' has principal moments of inertia ({:g}, {:g}, {:g}) kg m^2 in the state but "
                              "({:g}, {:g}, {:g}) kg m^2 in the scenario", b.name, moments[i].x, moments[i].y,
                              moments[i].z, b.principal_moments_kg_m2.x, b.principal_moments_kg_m2.y,
                              b.principal_moments_kg_m2.z);
        if (!why.empty()) throw InputError({file.path().string(), "", 0, 0}, restart_body_change(scenario, why));
    }
}

void read_bodies(const StateFile& file, const std::filesystem::path& scenario, World3d& w, bool restart) {
    const StateGroup g = file.root().open_group("bodies3d");
    const std::vector<std::string> name = g.strings("name");
    const std::size_t n = w.bodies.size();
    if (name.size() != n) refuse(file, scenario, fmt::format("the state has {} bodies, the scenario {}", name.size(), n));
    const auto count = static_cast<std::int64_t>(n);
    const std::vector<std::uint8_t> kind = g.flags("kind", count);
    const std::vector<std::uint32_t> vertices = g.indices("vertex_count", count);
    for (std::size_t i = 0; i < n; ++i) {
        if (name[i] != w.bodies[i].name)
            refuse(file, scenario, fmt::format("body {} is '{}' in the state but '{}' in the scenario", i + 1, name[i], w.bodies[i].name));
        if (kind[i] != static_cast<std::uint8_t>(w.kinds[i]) || vertices[i] != w.bodies[i].shape.vertices_m.size())
            refuse(file, scenario, fmt::format("body '{}' has another kind or shape in the state than in the scenario", name[i]));
    }
    check_shapes(file, scenario, g, w);
    if (restart) check_masses(file, scenario, g, w);
    const std::vector<Vec3> position = vec3s(g, "position_m", n), velocity = vec3s(g, "velocity_m_s", n),
                            momentum = vec3s(g, "angular_momentum_kg_m2_s", n),
                            omega_body = vec3s(g, "angular_velocity_body_rad_s", n),
                            velocity_t = vec3s(g, "velocity_at_t_m_s", n),
                            omega_t = vec3s(g, "angular_velocity_at_t_rad_s", n);
    const std::vector<double> q = g.doubles("orientation", 4 * count, 4);
    for (std::size_t i = 0; i < n; ++i) {
        RigidBody3d& b = w.bodies[i];
        b.position_m = position[i];
        b.orientation = {q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]};
        b.velocity_m_s = velocity[i];
        b.angular_momentum_kg_m2_s = momentum[i];
        b.angular_velocity_body_rad_s = omega_body[i];
        b.velocity_at_t_m_s = velocity_t[i];
        b.angular_velocity_at_t_rad_s = omega_t[i];
    }
}

std::vector<ContactPoint3d> read_contacts_3d(const StateGroup& g, std::size_t body_count) {
    const std::vector<std::uint32_t> a = g.indices("body_a");
    const std::size_t n = a.size();
    const auto count = static_cast<std::int64_t>(n);
    const std::vector<std::uint32_t> b = g.indices("body_b", count), fa = g.indices("feature_a", count),
                                     fb = g.indices("feature_b", count);
    const std::vector<Vec3> point = vec3s(g, "point_m", n), normal = vec3s(g, "normal", n),
                            spring = vec3s(g, "shear_spring_n", n), dashpot = vec3s(g, "shear_dashpot_n", n),
                            force = vec3s(g, "force_n", n);
    const std::vector<double> overlap = g.doubles("overlap_m", count),
                              normal_dashpot = g.doubles("normal_dashpot_n", count);
    const std::vector<std::uint8_t> sliding = g.flags("sliding", count);
    // A state written before the shares (every point a full kn) reads as shares of 1. The points'
    // dashpot_mass_kg is not read: the step and the stable bound make the masses from the bodies
    // and the shares (point_dashpot_masses_kg).
    const std::vector<double> share =
        g.has("stiffness_share") ? g.doubles("stiffness_share", count) : std::vector<double>(n, 1.0);
    std::vector<ContactPoint3d> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        ContactPoint3d& c = out[i];
        c.key = {a[i], b[i], fa[i], fb[i]};
        // The table is sorted by key, a < b: the history's merge pass relies on it.
        if (a[i] >= b[i] || b[i] >= body_count || (i > 0 && !(out[i - 1].key < c.key)))
            throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: {}: point {} is not a "
                                                               "valid entry of the contact table", g.path(), i + 1));
        c.point_m = point[i];
        c.normal = normal[i];
        c.overlap_m = overlap[i];
        c.stiffness_share = share[i];
        c.normal_dashpot_n = normal_dashpot[i];
        c.shear = {spring[i], dashpot[i]};
        c.sliding = sliding[i] != 0;
        c.force_n = force[i];
    }
    return out;
}

// Over the watch the scenario started (its start bound and ratio): a state saved before the live
// limit was the highest mode's lacks the ratio, which the scenario's start then gives.
StabilityWatch3d read_stability_3d(const StateGroup& g, StabilityWatch3d s) {
    if (g.has("limit_ratio")) {
        s.start_bound_s = g.number("start_bound_s");
        s.limit_ratio = g.number("limit_ratio");
        s.ratio_bound_s = g.number("ratio_bound_s");
        s.estimates = g.integer("estimates");
    }
    s.least_limit_s = g.number("least_limit_s");
    s.least_limit_body = g.text("least_limit_body");
    s.least_limit_time_s = g.number("least_limit_time_s");
    s.first_exceeded_s = g.number("first_exceeded_s");
    s.exceeded_body = g.text("exceeded_body");
    // The deepest overlap: absent from a state saved before it was watched (none seen then).
    if (g.has("max_overlap_ratio")) {
        s.max_overlap_ratio = g.number("max_overlap_ratio");
        s.max_overlap_m = g.number("max_overlap_m");
        s.max_overlap_time_s = g.number("max_overlap_time_s");
        s.max_overlap_body_a = static_cast<std::uint32_t>(g.integer("max_overlap_body_a"));
        s.max_overlap_body_b = static_cast<std::uint32_t>(g.integer("max_overlap_body_b"));
    }
    return s;
}

// The bodies that left the model (the extent itself comes from the scenario again).
void write_domain(StateGroup g, const ModelDomain3d& d) {
    std::vector<std::uint32_t> body;
    std::vector<double> time_s;
    std::vector<Vec3> position_m, velocity_m_s;
    for (const BodyLeftModel3d& l : d.left) {
        body.push_back(l.body);
        time_s.push_back(l.time_s);
        position_m.push_back(l.position_m);
        velocity_m_s.push_back(l.velocity_m_s);
    }
    g.write("left_body", body);
    g.write("left_time_s", time_s);
    g.write("left_position_m", flat(position_m), 3);
    g.write("left_velocity_m_s", flat(velocity_m_s), 3);
}

void read_domain(const StateGroup& g, World3d& w) {
    const std::vector<std::uint32_t> body = g.indices("left_body");
    const auto left = static_cast<std::int64_t>(body.size());
    const std::vector<double> time_s = g.doubles("left_time_s", left);
    const std::vector<Vec3> position_m = vec3s(g, "left_position_m", body.size());
    const std::vector<Vec3> velocity_m_s = vec3s(g, "left_velocity_m_s", body.size());
    w.domain.left.clear();
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (body[i] >= w.bodies.size())
            throw InputError({g.file(), "", 0, 0}, fmt::format("not a readable blockdem state file: /domain3d/left_body: "
                                                               "body {} of {}", body[i], w.bodies.size()));
        w.domain.left.push_back({body[i], time_s[i], position_m[i], velocity_m_s[i]});
    }
    mark_taken_out(w);
}

}  // namespace

void write_world_3d(StateGroup& root, const World3d& w) {
    root.set("dt_s", w.dt_s);
    write_bodies(root.create_group("bodies3d"), w);
    write_contacts(root.create_group("contacts3d"), w);
    write_ledger(root.create_group("energy"), w.ledger);
    write_stability(root.create_group("stability3d"), w.stability);
    write_domain(root.create_group("domain3d"), w.domain);
    // (Only while a caller's loads exist: the files of runs without them stay as they were.)
    if (w.external_loads.any()) write_external_loads(root.create_group("external_loads3d"), w.external_loads);
}

namespace {

void check_dimension(const StateFile& file, const std::filesystem::path& scenario) {
    if (file.dimension() != 3)
        throw InputError({file.path().string(), "", 0, 0},
                         fmt::format("a {}-D state: scenario {} is 3-D", file.dimension(), scenario.string()));
}

}  // namespace

void start_from_state_3d(const StateFile& file, World3d& w, const std::filesystem::path& scenario) {
    check_dimension(file, scenario);
    read_bodies(file, scenario, w, false);
    replace_contacts(w, read_contacts_3d(file.root().open_group("contacts3d"), w.bodies.size()));
    // As settling ends (world/settling_3d.cpp): the velocities at the state's time become the
    // initial ones, and the first step is the half step from an initial state.
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.kinds[i] == BodyKind3d::dynamic)
            set_initial_velocity(w.bodies[i], w.bodies[i].velocity_at_t_m_s, w.bodies[i].angular_velocity_at_t_rad_s);
    w.time_s = 0.0;
    w.steps = 0;
    w.ledger = EnergyLedger{};
}

void restore_world_3d(const StateFile& file, World3d& w, const std::filesystem::path& scenario) {
    const InputLocation where{file.path().string(), "", 0, 0};
    check_dimension(file, scenario);
    const StateGroup& root = file.root();
    read_bodies(file, scenario, w, true);  // (first: a state of another scenario is told as such)
    const double dt_s = root.number("dt_s");
    if (dt_s != w.dt_s)
        throw InputError(where, fmt::format("the state was saved with dt = {:.17g} s, scenario {} gives dt = {:.17g} s: a "
                                            "restart keeps the time step",
                                            dt_s, scenario.string(), w.dt_s));
    replace_contacts(w, read_contacts_3d(root.open_group("contacts3d"), w.bodies.size()));
    w.ledger = read_ledger(root.open_group("energy"));
    w.stability = read_stability_3d(root.open_group("stability3d"), w.stability);
    if (w.stability.max_overlap_body_a >= w.bodies.size() || w.stability.max_overlap_body_b >= w.bodies.size())
        throw InputError(where, "not a readable blockdem state file: /stability3d/max_overlap_body_a or _b names no body");
    check_live_limit_ratio(where.file, "/stability3d", w.stability.limit_ratio, w.stability.ratio_bound_s,
                           w.stability.estimates);
    if (root.has("domain3d")) read_domain(root.open_group("domain3d"), w);  // (files of earlier versions lack it)
    // A caller's loads as saved; none without the group (a run without loads, or an earlier file),
    // also when w had some (a world going back to a checkpoint).
    w.external_loads = root.has("external_loads3d") ? read_external_loads_3d(root.open_group("external_loads3d"), w.bodies.size())
                                                    : ExternalLoads3d{};
    w.time_s = file.time_s();
    w.steps = file.step_index();
}

namespace {

// The monitor's numbers per body, one dataset each (the names are BodyResponse3d's fields).
struct Number3dField {
    const char* name;
    double BodyResponse3d::*field;
};
constexpr Number3dField number_3d_fields[] = {
    {"overturning_angle_rad", &BodyResponse3d::overturning_angle_rad},
    {"peak_tilt_rad", &BodyResponse3d::peak_tilt_rad},
    {"peak_tilt_time_s", &BodyResponse3d::peak_tilt_time_s},
    {"peak_slip_m", &BodyResponse3d::peak_slip_m},
    {"last_crossing_s", &BodyResponse3d::last_crossing_s},
    {"height_m", &BodyResponse3d::height_m},
    {"base_width_m", &BodyResponse3d::base_width_m},
    {"bounding_radius_m", &BodyResponse3d::bounding_radius_m},
    {"peak_base_slip_m", &BodyResponse3d::peak_base_slip_m},
    {"peak_elastic_shear_m", &BodyResponse3d::peak_elastic_shear_m},
    {"rocking_onset_s", &BodyResponse3d::rocking_onset_s},
    {"slip_onset_s", &BodyResponse3d::slip_onset_s},
    {"support_lost_time_s", &BodyResponse3d::support_lost_time_s},
    {"drop_time_s", &BodyResponse3d::drop_time_s},
};

struct Flag3dField {
    const char* name;
    bool BodyResponse3d::*field;
    bool absent_means_true = false;  ///< a flag that states from before it lack: taken as true
};
constexpr Flag3dField flag_3d_fields[] = {
    {"beyond_limit", &BodyResponse3d::beyond_limit},
    {"touches_a_supporter", &BodyResponse3d::touches_a_supporter},
    {"at_rest", &BodyResponse3d::at_rest},
    {"slid_on_support", &BodyResponse3d::slid_on_support},
    {"touched_a_body", &BodyResponse3d::touched_a_body, true},
    {"rested_on_ground", &BodyResponse3d::rested_on_ground, true},
};

}  // namespace

void Monitor3dStatePart::save_state(StateGroup& g) const {
    const std::vector<BodyResponse3d>& r = monitor_.bodies();
    using R = BodyResponse3d;
    g.write("start_position_m", flat(column<Vec3>(r, [](const R& x) { return x.start_position_m; })), 3);
    std::vector<double> q;
    for (const R& x : r) q.insert(q.end(), {x.start_orientation.w, x.start_orientation.x, x.start_orientation.y, x.start_orientation.z});
    g.write("start_orientation", q, 4);
    g.write("peak_tilt_axis", flat(column<Vec3>(r, [](const R& x) { return x.peak_tilt_axis; })), 3);
    for (const Number3dField& f : number_3d_fields) g.write(f.name, column<double>(r, [&](const R& x) { return x.*f.field; }));
    for (const Flag3dField& f : flag_3d_fields)
        g.write(f.name, column<std::uint8_t>(r, [&](const R& x) { return std::uint8_t(x.*f.field ? 1 : 0); }));
    // (The resting face is found again from the scenario at t = 0.) Each body's supporters: supporters[supporters_start[i] .. supporters_start[i + 1]).
    std::vector<std::uint32_t> start{0}, supporters;
    for (const R& x : r) {
        supporters.insert(supporters.end(), x.supporters.begin(), x.supporters.end());
        start.push_back(static_cast<std::uint32_t>(supporters.size()));
    }
    g.write("supporters_start", start);
    g.write("supporters", supporters);
}

void Monitor3dStatePart::restore_state(const StateGroup& g) {
    std::vector<BodyResponse3d> r = monitor_.bodies();
    const std::size_t n = r.size();
    const auto count = static_cast<std::int64_t>(n);
    const std::vector<Vec3> start = vec3s(g, "start_position_m", n), axis = vec3s(g, "peak_tilt_axis", n);
    const std::vector<double> q = g.doubles("start_orientation", 4 * count, 4);
    for (std::size_t i = 0; i < n; ++i) {
        r[i].start_position_m = start[i];
        r[i].start_orientation = {q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]};
        r[i].peak_tilt_axis = axis[i];
    }
    for (const Number3dField& f : number_3d_fields) {
        const std::vector<double> values = g.doubles(f.name, count);
        for (std::size_t i = 0; i < n; ++i) r[i].*f.field = values[i];
    }
    for (const Flag3dField& f : flag_3d_fields) {
        const std::vector<std::uint8_t> values =
            f.absent_means_true && !g.has(f.name) ? std::vector<std::uint8_t>(count, 1) : g.flags(f.name, count);
        for (std::size_t i = 0; i < n; ++i) r[i].*f.field = values[i] != 0;
    }
    const std::vector<std::uint32_t> first = g.indices("supporters_start", count + 1);
    const std::vector<std::uint32_t> supporters = g.indices("supporters", first.back());
    for (std::size_t i = 0; i < n; ++i) {
        if (first[i] > first[i + 1])
            throw InputError({g.file(), "", 0, 0}, "not a readable blockdem state file: /monitor3d/supporters_start is not "
                                                   "increasing");
        r[i].supporters.assign(supporters.begin() + first[i], supporters.begin() + first[i + 1]);
        for (std::uint32_t s : r[i].supporters)
            if (s >= n)
                throw InputError({g.file(), "", 0, 0}, "not a readable blockdem state file: /monitor3d/supporters names no body");
    }
    monitor_.restore(std::move(r));
}

void Vtk3dStatePart::save_state(StateGroup& g) const { g.write("frame_times_s", writer_.frame_times_s()); }

void Vtk3dStatePart::restore_state(const StateGroup& g) {
    std::vector<double> times = g.doubles("frame_times_s");
    // (Frames are taken at output times, which are whole steps: half a step tells before from at.)
    while (!times.empty() && times.back() > world_.time_s - 0.5 * world_.dt_s) times.pop_back();
    writer_.continue_after(std::move(times));
}

}  // namespace blockdem
