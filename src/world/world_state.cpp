#include "world/world_state.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "contact/contact_forces.hpp"
#include "dynamics/central_difference.hpp"
#include "world/step.hpp"

namespace blockdem {

WorldState capture_state(const World& w) {
    const Bodies& b = w.bodies;
    WorldState s;
    s.time_s = w.time_s;
    s.step_index = w.step_index;
    s.dt_s = w.dt_s;
    s.critical_dt_s = w.critical_dt_s;
    s.proven_stable_dt_s = w.proven_stable_dt_s;
    s.settling_time_s = w.settling_time_s;
    s.settling = w.settling;
    s.velocities_staggered = w.velocities_staggered;
    s.broad_phase_rebuilds = w.broad_phase_rebuilds;
    s.name = b.name;
    s.kind = b.kind;
    s.vertex_count = b.vertex_count;
    // The outlines only: a concave body's parts follow from its outline (world.cpp).
    const auto outline_end = static_cast<std::ptrdiff_t>(b.outline_corners());
    s.local_vertices_m.assign(b.local_vertices_m.begin(), b.local_vertices_m.begin() + outline_end);
    s.mass_kg = b.mass_kg;
    s.inertia_kg_m2 = b.inertia_kg_m2;
    s.is_static = b.is_static;
    s.position_m = b.position_m;
    s.rotation_rad = b.rotation_rad;
    s.velocity_m_s = b.velocity_m_s;
    s.angular_velocity_rad_s = b.angular_velocity_rad_s;
    s.velocity_at_t_m_s = b.velocity_at_t_m_s;
    s.angular_velocity_at_t_rad_s = b.angular_velocity_at_t_rad_s;
    s.initial_position_m = b.initial_position_m;
    s.world_vertices_m.assign(b.world_vertices_m.begin(), b.world_vertices_m.begin() + outline_end);
    s.world_normals.assign(b.world_normals.begin(), b.world_normals.begin() + outline_end);
    s.position_at_rebuild_m = b.position_at_rebuild_m;
    s.rotation_at_rebuild_rad = b.rotation_at_rebuild_rad;
    s.contacts = w.contacts;
    s.sub_contacts = w.sub_contacts;
    s.energy = w.energy;
    s.stability = w.stability;
    s.left = w.domain.left;
    s.external_loads = w.external_loads;
    return s;
}

std::optional<std::string> state_mismatch(const World& w, const WorldState& s) {
    const Bodies& b = w.bodies;
    if (s.name.size() != b.size())
        return fmt::format("the state has {} bodies, the scenario {}", s.name.size(), b.size());
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (s.name[i] != b.name[i])
            return fmt::format("body {} is '{}' in the state but '{}' in the scenario", i + 1, s.name[i], b.name[i]);
        if (s.kind[i] != b.kind[i])
            return fmt::format("body '{}' is {} in the state but {} in the scenario", b.name[i], to_string(s.kind[i]),
                               to_string(b.kind[i]));
        if (s.vertex_count[i] != b.vertex_count[i])
            return fmt::format("body '{}' has {} corners in the state but {} in the scenario", b.name[i],
                               s.vertex_count[i], b.vertex_count[i]);
    }
    // The same corners relative to the centroid (exactly: both come from the same numbers).
    for (std::size_t i = 0; i < b.size(); ++i)
        for (std::uint32_t k = b.vertex_begin[i]; k < b.vertex_begin[i] + b.vertex_count[i]; ++k)
            if (s.local_vertices_m[k].x != b.local_vertices_m[k].x || s.local_vertices_m[k].y != b.local_vertices_m[k].y)
                return fmt::format("body '{}' has another shape in the state than in the scenario (corner {})", b.name[i],
                                   k - b.vertex_begin[i] + 1);
    // The contact table's parts must be parts of its bodies (the same outlines cut the same way).
    for (std::size_t p = 0; p < s.contacts.size(); ++p) {
        const PairContact& pair = s.contacts[p];
        if (pair.part_a >= b.part_total() || pair.part_b >= b.part_total() || b.part_body[pair.part_a] != pair.a ||
            b.part_body[pair.part_b] != pair.b)
            return fmt::format("contact pair {} of the state joins parts {} and {}, which are not parts of bodies '{}' and "
                               "'{}' in the scenario", p + 1, pair.part_a, pair.part_b, b.name[pair.a], b.name[pair.b]);
    }
    return std::nullopt;
}

std::optional<std::string> mass_mismatch(const World& w, const WorldState& s) {
    const Bodies& b = w.bodies;
    if (s.mass_kg.size() != b.size() || s.inertia_kg_m2.size() != b.size()) return std::nullopt;
    // (The same scenario gives the same numbers: the tolerance only forgives the last digit.)
    const auto differs = [](double a, double c) { return std::abs(a - c) > 1e-12 * std::max(std::abs(a), std::abs(c)); };
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::dynamic) continue;
        if (differs(s.mass_kg[i], b.mass_kg[i]))
            return fmt::format("body '{}' has mass {:g} kg in the state but {:g} kg in the scenario (its density or size "
                               "changed)", b.name[i], s.mass_kg[i], b.mass_kg[i]);
        if (differs(s.inertia_kg_m2[i], b.inertia_kg_m2[i]))
            return fmt::format("body '{}' has moment of inertia {:g} kg m^2 in the state but {:g} kg m^2 in the scenario "
                               "(its density or size changed)", b.name[i], s.inertia_kg_m2[i], b.inertia_kg_m2[i]);
    }
    return std::nullopt;
}

namespace {

// The bodies' state and the contact table, as saved; the clock is left to the caller.
void restore_bodies_and_contacts(World& w, const WorldState& s, bool dynamic_only) {
    Bodies& b = w.bodies;
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (dynamic_only && b.kind[i] != BodyKind::dynamic) continue;
        b.position_m[i] = s.position_m[i];
        b.rotation_rad[i] = s.rotation_rad[i];
        b.velocity_m_s[i] = s.velocity_m_s[i];
        b.angular_velocity_rad_s[i] = s.angular_velocity_rad_s[i];
        b.velocity_at_t_m_s[i] = s.velocity_at_t_m_s[i];
        b.angular_velocity_at_t_rad_s[i] = s.angular_velocity_at_t_rad_s[i];
        b.initial_position_m[i] = s.initial_position_m[i];
        for (std::uint32_t k = b.vertex_begin[i]; k < b.vertex_begin[i] + b.vertex_count[i]; ++k) {
            b.world_vertices_m[k] = s.world_vertices_m[k];
            b.world_normals[k] = s.world_normals[k];
        }
    }
    b.corner_offsets_rounding_m = 0.0;  // (made from the normals written over: the next step remakes them)
    b.position_at_rebuild_m = s.position_at_rebuild_m;
    b.rotation_at_rebuild_rad = s.rotation_at_rebuild_rad;
    w.velocities_staggered = s.velocities_staggered;
    w.broad_phase_rebuilds = s.broad_phase_rebuilds;
    w.settling_time_s = s.settling_time_s;
    w.settling = s.settling;
    w.stability = s.stability;
    w.contacts = s.contacts;
    // (A state saved without sub-contacts gives this run's interior points fresh, unbonded.)
    w.sub_contacts = s.sub_contacts;
    if (w.contact.sub_contacts <= 2)
        w.sub_contacts.clear();
    else if (w.sub_contacts.size() != w.contacts.size())
        w.sub_contacts.assign(w.contacts.size(), SubContacts{});
    w.candidate_pairs.clear();
    for (const PairContact& pair : w.contacts) w.candidate_pairs.emplace_back(pair.part_a, pair.part_b);
    index_pairs_by_body(w);
    // Bodies taken out of the model stay out: static, and moved by no force.
    w.domain.left = s.left;
    for (const BodyLeftModel& left : s.left) {
        b.is_static[left.body] = 1;
        b.inv_mass_1_kg[left.body] = 0.0;
        b.inv_inertia_1_kg_m2[left.body] = 0.0;
    }
}

}  // namespace

void restore_state(World& w, const WorldState& s) {
    restore_bodies_and_contacts(w, s, false);
    w.time_s = s.time_s;
    w.step_index = s.step_index;
    w.energy = s.energy;
    w.external_loads = s.external_loads;
}

void start_from_state(World& w, const WorldState& s) {
    restore_bodies_and_contacts(w, s, true);
    // As settling ends (world/settling.cpp): the clock and the ledger start again here.
    w.time_s = 0.0;
    w.step_index = 0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies.kind[i] == BodyKind::dynamic) w.bodies.initial_position_m[i] = w.bodies.position_m[i];
    place_driven_bodies(w, 0.0);
    w.energy = EnergyLedger{};
    initialise_energy(w);
}

}  // namespace blockdem
