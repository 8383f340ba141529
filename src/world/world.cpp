#include "world/world.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "contact/bonded_pairs.hpp"
#include "contact/narrow_phase.hpp"
#include "dynamics/central_difference.hpp"
#include "dynamics/critical_time_step.hpp"
#include "dynamics/highest_mode.hpp"
#include "geometry/outline.hpp"
#include "geometry/polygon.hpp"
#include "geometry/rounded_contact.hpp"
#include "geometry/rounded_outline.hpp"
#include "world/settling.hpp"
#include "world/simulation_error.hpp"
#include "world/step.hpp"

namespace blockdem {

std::uint32_t World::body_id(const std::string& wanted) const {
    const auto it = std::find(bodies.name.begin(), bodies.name.end(), wanted);
    if (it == bodies.name.end()) throw std::out_of_range("no body named '" + wanted + "'");
    return static_cast<std::uint32_t>(it - bodies.name.begin());
}

namespace {

// The outward unit normals of a counter-clockwise convex polygon's edges (edge k: corner k to k+1).
std::vector<Vec2> part_normals(const std::vector<Vec2>& part) {
    std::vector<Vec2> normals;
    for (std::size_t k = 0; k < part.size(); ++k) normals.push_back(edge_normal(part[k], part[(k + 1) % part.size()]));
    return normals;
}

// Adds body def with its outline's corners; returns its convex parts (relative to the world
// origin) and their seam flags, whose corners build_world appends after every outline.
RoundedOutlineParts add_body(Bodies& b, const BodyDef& def, const MaterialPairs& contact) {
    if (auto problem = outline_problem(def.vertices_m)) throw ModelError(fmt::format("body '{}': {}", def.name, *problem));
    std::vector<std::vector<Vec2>> parts;
    try {
        parts = outline_parts(def.vertices_m);
    } catch (const std::invalid_argument& e) {
        throw ModelError(fmt::format("body '{}': its outline cannot be cut into convex parts: {}", def.name, e.what()));
    }
    double thinnest = INFINITY;
    for (const std::vector<Vec2>& part : parts) {
        if (auto problem = convexity_problem(part))
            throw ModelError(fmt::format("body '{}': a convex part of its outline is not valid: {}", def.name, *problem));
        thinnest = std::min(thinnest, least_width(part));
        // Rounded corners are those of each convex part: every part must keep a core.
        if (auto problem = rounding_problem(part, part_normals(part), least_width(part), contact.rounding_m))
            throw ModelError(fmt::format("body '{}': {}", def.name, *problem));
    }
    // With rounded corners a concave body's parts are those of its rounded outline: only the
    // outline's own corners are arcs (geometry/rounded_outline.hpp).
    RoundedOutlineParts contact_parts{parts, std::vector<std::vector<std::uint8_t>>(parts.size())};
    if (parts.size() > 1 && contact.rounding_m > 0.0) {
        try {
            contact_parts = rounded_outline_parts(def.vertices_m, contact.rounding_m);
        } catch (const std::invalid_argument& e) {
            throw ModelError(fmt::format("body '{}': {}", def.name, e.what()));
        }
    }
    // The shoelace sums of polygon_properties hold for any simple polygon, convex or not: the
    // union's area, centroid and polar moment in closed form, not summed over the parts.
    const PolygonProperties props = polygon_properties(def.vertices_m);
    double mass = def.mass_kg.value_or(def.density_kg_m3 * props.area_m2 * def.thickness_m);
    if (def.kind == BodyKind::dynamic && !(mass > 0.0))
        throw ModelError(fmt::format("body '{}': mass must be > 0 (give density or mass), got {} kg", def.name, mass));
    // Inertia of a uniform plate: mass times the polar radius of gyration squared.
    const double inertia = def.inertia_kg_m2.value_or(mass * props.polar_moment_m4 / props.area_m2);
    if (def.kind == BodyKind::dynamic && !(inertia > 0.0))
        throw ModelError(fmt::format("body '{}': moment of inertia must be > 0, got {} kg m^2", def.name, inertia));
    std::uint32_t material = 0;
    try {
        material = contact.id(def.material);
    } catch (const std::out_of_range&) {
        throw ModelError(fmt::format("body '{}': unknown material '{}'", def.name, def.material));
    }
    const bool dynamic = def.kind == BodyKind::dynamic;
    b.name.push_back(def.name);
    b.kind.push_back(def.kind);
    b.is_static.push_back(dynamic ? 0 : 1);
    b.record.push_back(def.record ? 1 : 0);
    b.assembly.push_back(def.assembly);
    b.material.push_back(material);
    b.mass_kg.push_back(mass);
    b.inv_mass_1_kg.push_back(dynamic ? 1.0 / mass : 0.0);
    b.inertia_kg_m2.push_back(inertia);
    b.inv_inertia_1_kg_m2.push_back(dynamic ? 1.0 / inertia : 0.0);
    b.vertex_begin.push_back(static_cast<std::uint32_t>(b.local_vertices_m.size()));
    b.vertex_count.push_back(static_cast<std::uint32_t>(def.vertices_m.size()));
    double radius = 0.0;
    for (Vec2 v : def.vertices_m) {
        b.seam_corner.push_back(0);
        b.local_vertices_m.push_back(v - props.centroid_m);
        radius = std::max(radius, length(v - props.centroid_m));
    }
    b.bounding_radius_m.push_back(radius);
    b.least_width_m.push_back(thinnest);
    b.thickness_m.push_back(def.thickness_m);
    b.bond_group.push_back(def.bond_group);
    const std::size_t first = b.local_vertices_m.size() - def.vertices_m.size();
    for (std::size_t k = 0; k < def.vertices_m.size(); ++k)
        b.local_normals.push_back(
            edge_normal(b.local_vertices_m[first + k], b.local_vertices_m[first + (k + 1) % def.vertices_m.size()]));
    b.position_m.push_back(props.centroid_m);
    b.initial_position_m.push_back(props.centroid_m);
    b.rotation_rad.push_back(0.0);
    b.velocity_m_s.push_back(dynamic ? def.velocity_m_s : Vec2{});
    b.angular_velocity_rad_s.push_back(dynamic ? def.angular_velocity_rad_s : 0.0);
    b.velocity_at_t_m_s.push_back(b.velocity_m_s.back());
    b.angular_velocity_at_t_rad_s.push_back(b.angular_velocity_rad_s.back());
    return contact_parts;
}

// The parts of body i: a convex body's one part is its outline; a concave body's parts get
// their own corners after every outline, so that outputs and state files see outlines only.
void add_parts(Bodies& b, std::uint32_t i, const RoundedOutlineParts& contact_parts) {
    const std::vector<std::vector<Vec2>>& parts = contact_parts.parts;
    b.part_begin.push_back(static_cast<std::uint32_t>(b.part_body.size()));
    b.part_count.push_back(static_cast<std::uint32_t>(parts.size()));
    if (parts.size() == 1) {
        b.part_body.push_back(i);
        b.part_vertex_begin.push_back(b.vertex_begin[i]);
        b.part_vertex_count.push_back(b.vertex_count[i]);
        b.part_radius_m.push_back(b.bounding_radius_m[i]);
        return;
    }
    const Vec2 centroid = b.position_m[i];
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const std::vector<Vec2>& part = parts[p];
        const Vec2 own_centroid = polygon_properties(part).centroid_m;
        const auto first = static_cast<std::uint32_t>(b.local_vertices_m.size());
        double radius = 0.0;
        for (std::size_t k = 0; k < part.size(); ++k) b.seam_corner.push_back(contact_parts.seam[p].empty() ? 0 : contact_parts.seam[p][k]);
        for (Vec2 v : part) {
            b.local_vertices_m.push_back(v - centroid);
            radius = std::max(radius, length(v - own_centroid));
        }
        for (std::size_t k = 0; k < part.size(); ++k)
            b.local_normals.push_back(edge_normal(b.local_vertices_m[first + k], b.local_vertices_m[first + (k + 1) % part.size()]));
        b.part_body.push_back(i);
        b.part_vertex_begin.push_back(first);
        b.part_vertex_count.push_back(static_cast<std::uint32_t>(part.size()));
        b.part_radius_m.push_back(radius);
    }
}

void check_no_initial_overlap(World& w) {
    update_body_geometry(w);
    rebuild_candidate_pairs(w);
    update_contact_geometry(w);
    for (const PairContact& pair : w.contacts) {
        for (std::uint32_t i = 0; i < pair.count; ++i) {
            const double size = std::min(w.bodies.bounding_radius_m[pair.a], w.bodies.bounding_radius_m[pair.b]);
            // Touching is fine (bricks laid exactly side by side); overlap beyond round-off is not.
            if (pair.points[i].overlap_m > 1e-9 * size)
                throw ModelError(fmt::format("bodies '{}' and '{}' overlap at the start by {:.3g} m at ({:.6g}, {:.6g}) m",
                                             w.bodies.name[pair.a], w.bodies.name[pair.b], pair.points[i].overlap_m,
                                             pair.points[i].point_m.x, pair.points[i].point_m.y));
        }
    }
}

// The stable limits of the start configuration, and dt: the given one, checked against the
// highest mode's limit, or dt_safety times that limit.
void set_time_step(World& w, const SimulationSettings& settings) {
    const StartTimeStep start = critical_time_step(w);
    const CriticalTimeStep& limit = start.highest_mode;
    w.critical_dt_s = limit.dt_s;
    w.proven_stable_dt_s = start.proven.dt_s;
    w.stability.start_bound_s = start.proven.dt_s;
    w.stability.limit_ratio = start_limit_ratio(limit.dt_s, start.proven.dt_s);
    w.stability.ratio_bound_s = w.stability.limit_ratio > 0.0 ? start.proven.dt_s : 0.0;
    w.stability.least_limit_s = limit.dt_s;
    w.stability.least_limit_body = limit.body;
    if (settings.dt_s) {
        w.dt_s = *settings.dt_s;
        if (w.dt_s > limit.dt_s)
            throw ModelError(fmt::format("time step dt = {:g} s is above the stable limit {:.4g} s of the highest contact "
                                         "mode at the start (mostly body '{}': frequency {:.4g} rad/s, damping ratio "
                                         "{:.3g}); use dt <= {:.3g} s (every dt <= {:.3g} s is proven stable)",
                                         w.dt_s, limit.dt_s, limit.body, limit.omega_rad_s, limit.h,
                                         default_dt_safety * limit.dt_s, start.proven.dt_s));
    } else {
        if (!std::isfinite(limit.dt_s))
            throw ModelError("cannot derive the time step: no dynamic body; give simulation.dt");
        // Rounded down to a whole number of steps per output interval, so that the rows of
        // history.csv fall at t = n x output_interval (0.001, 0.002, ... not 0.0010017, ...).
        const double largest_s = settings.dt_safety * limit.dt_s;
        const double steps = std::ceil(settings.output_interval_s / largest_s);
        w.dt_s = steps <= 1e9 ? std::min(largest_s, settings.output_interval_s / steps) : largest_s;
    }
}

}  // namespace

Aabb body_box(const Bodies& b, std::size_t i) {
    Aabb box = b.part_box_m[b.part_begin[i]];
    for (std::uint32_t j = b.part_begin[i] + 1; j < b.part_begin[i] + b.part_count[i]; ++j) {
        box.lo = {std::min(box.lo.x, b.part_box_m[j].lo.x), std::min(box.lo.y, b.part_box_m[j].lo.y)};
        box.hi = {std::max(box.hi.x, b.part_box_m[j].hi.x), std::max(box.hi.y, b.part_box_m[j].hi.y)};
    }
    return box;
}

namespace {

template <class T>
std::size_t bytes_of(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

}  // namespace

std::size_t memory_bytes(const World& w) {
    const Bodies& b = w.bodies;
    std::size_t total = sizeof(World) + bytes_of(b.name) + bytes_of(b.kind) + bytes_of(b.is_static) + bytes_of(b.record) +
                        bytes_of(b.material) + bytes_of(b.mass_kg) + bytes_of(b.inv_mass_1_kg) + bytes_of(b.inertia_kg_m2) +
                        bytes_of(b.inv_inertia_1_kg_m2) + bytes_of(b.bounding_radius_m) + bytes_of(b.least_width_m) + bytes_of(b.thickness_m) + bytes_of(b.bond_group) + bytes_of(b.vertex_begin) +
                        bytes_of(b.vertex_count) + bytes_of(b.part_begin) + bytes_of(b.part_count) + bytes_of(b.part_body) +
                        bytes_of(b.part_vertex_begin) + bytes_of(b.part_vertex_count) + bytes_of(b.part_radius_m) +
                        bytes_of(b.part_box_m) + bytes_of(b.local_vertices_m) + bytes_of(b.world_vertices_m) + bytes_of(b.local_normals) +
                        bytes_of(b.world_normals) + bytes_of(b.position_m) + bytes_of(b.rotation_rad) +
                        bytes_of(b.velocity_m_s) + bytes_of(b.angular_velocity_rad_s) + bytes_of(b.acceleration_m_s2) +
                        bytes_of(b.angular_acceleration_rad_s2) + bytes_of(b.velocity_at_t_m_s) +
                        bytes_of(b.angular_velocity_at_t_rad_s) + bytes_of(b.force_n) + bytes_of(b.torque_n_m) +
                        bytes_of(b.initial_position_m) + bytes_of(b.position_at_rebuild_m) +
                        bytes_of(b.rotation_at_rebuild_rad) + bytes_of(b.seam_corner);
    for (const std::string& name : b.name)
        if (name.capacity() > 15) total += name.capacity() + 1;  // beyond the small-string buffer
    total += bytes_of(w.boxes) + bytes_of(w.part_is_static) + bytes_of(w.candidate_pairs) + bytes_of(w.contacts) + bytes_of(w.contacts_scratch) +
             bytes_of(w.pair_forces) + bytes_of(w.body_pair_start) + bytes_of(w.body_pair_entries) +
             bytes_of(w.contacts_fill) + bytes_of(w.driven_bodies);
    total += w.broad_phase.memory_bytes();
    return total;
}

World build_world(const Model& model, const std::atomic<bool>* stop_requested) {
    World w;
    w.settings = model.settings;
    w.contact = model.contact;
    w.table_motion = model.table_motion;
    std::vector<RoundedOutlineParts> parts;
    for (const BodyDef& def : model.bodies) parts.push_back(add_body(w.bodies, def, w.contact));
    const std::size_t n = w.bodies.size();
    for (std::size_t i = 0; i < n; ++i) add_parts(w.bodies, static_cast<std::uint32_t>(i), parts[i]);
    w.bodies.world_vertices_m.resize(w.bodies.local_vertices_m.size());
    w.bodies.world_normals.resize(w.bodies.local_vertices_m.size());
    w.bodies.part_box_m.resize(w.bodies.part_total());
    w.bodies.acceleration_m_s2.assign(n, {});
    w.bodies.angular_acceleration_rad_s2.assign(n, 0.0);
    w.bodies.force_n.assign(n, {});
    w.bodies.torque_n_m.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        if (w.bodies.kind[i] == BodyKind::driven) w.driven_bodies.push_back(static_cast<std::uint32_t>(i));

    double smallest = INFINITY;
    for (std::size_t i = 0; i < n; ++i) smallest = std::min(smallest, w.bodies.bounding_radius_m[i]);
    w.broad_phase_margin_m = 0.1 * smallest;
    place_driven_bodies(w, 0.0);
    check_no_initial_overlap(w);
    bond_touching_pairs(w);
    set_time_step(w, model.settings);
    init_model_domain(w);
    initialise_energy(w);
    if (model.settling) {
        const SettlingReport settled = settle(w, *model.settling, stop_requested);
        if (settled.stopped) throw SettlingStopped(settled);
        // A run that started and could not settle failed (exit 3), it is not bad input.
        if (!settled.settled) throw SimulationError(settling_failure(settled, *model.settling));
        w.settling_time_s = settled.time_s;
        w.settling = settling_record(settled, *model.settling);
    }
    return w;
}

}  // namespace blockdem
