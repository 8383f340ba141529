#include "world/external_loads.hpp"

#include "world/world.hpp"

namespace blockdem {

namespace {

ExternalLoads& allocated_loads(World& w) {
    ExternalLoads& loads = w.external_loads;
    if (!loads.any()) {
        loads.force_n.assign(w.bodies.size(), Vec2{});
        loads.torque_n_m.assign(w.bodies.size(), 0.0);
        loads.held.assign(w.bodies.size(), 0);
        loads.held_velocity_m_s.assign(w.bodies.size(), Vec2{});
        loads.held_angular_velocity_rad_s.assign(w.bodies.size(), 0.0);
    }
    return loads;
}

}  // namespace

void set_external_load(World& w, std::uint32_t i, Vec2 force_n, double torque_n_m) {
    ExternalLoads& loads = allocated_loads(w);
    loads.force_n[i] = force_n;
    loads.torque_n_m[i] = torque_n_m;
}

void clear_external_loads(World& w) {
    ExternalLoads& loads = w.external_loads;
    loads.force_n.clear();
    loads.torque_n_m.clear();
    loads.held.clear();
    loads.held_velocity_m_s.clear();
    loads.held_angular_velocity_rad_s.clear();
}

void hold_body_velocity(World& w, std::uint32_t i, Vec2 velocity_m_s, double angular_velocity_rad_s) {
    // From t on, as set_body_velocity (this step's half-step velocity is already computed); the
    // held load keeps it from the next velocity update on.
    set_body_velocity(w, i, velocity_m_s, angular_velocity_rad_s);
    ExternalLoads& loads = allocated_loads(w);
    loads.held[i] = 1;
    loads.held_velocity_m_s[i] = velocity_m_s;
    loads.held_angular_velocity_rad_s[i] = angular_velocity_rad_s;
}

void release_body_velocity(World& w, std::uint32_t i) {
    if (!w.external_loads.any()) return;
    w.external_loads.held[i] = 0;
    set_external_load(w, i, Vec2{}, 0.0);
}

void add_external_load(World& w, std::size_t i) {
    // (Only dynamic bodies move; a static body's sums are not used for its motion.)
    Bodies& b = w.bodies;
    ExternalLoads& loads = w.external_loads;
    if (loads.held[i] != 0 && b.kind[i] == BodyKind::dynamic) {
        // The total force that takes the stored velocity to the held one over the coming
        // velocity update (central_difference.hpp: a whole step, or the first half step while
        // the velocities are not yet staggered); the load is what the contacts and gravity lack.
        const double span_s = w.velocities_staggered ? w.dt_s : 0.5 * w.dt_s;
        const Vec2 total_n = (b.mass_kg[i] / span_s) * (loads.held_velocity_m_s[i] - b.velocity_m_s[i]);
        const double total_n_m = b.inertia_kg_m2[i] / span_s * (loads.held_angular_velocity_rad_s[i] - b.angular_velocity_rad_s[i]);
        loads.force_n[i] = total_n - b.force_n[i];
        loads.torque_n_m[i] = total_n_m - b.torque_n_m[i];
    }
    b.force_n[i] += loads.force_n[i];
    b.torque_n_m[i] += loads.torque_n_m[i];
}

double external_load_work(const World& w) {
    const Bodies& b = w.bodies;
    double work_j = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.is_static[i]) continue;
        const Vec2 f = w.external_loads.force_n[i];
        work_j += (f.x * b.velocity_m_s[i].x + f.y * b.velocity_m_s[i].y + w.external_loads.torque_n_m[i] * b.angular_velocity_rad_s[i]) * w.dt_s;
    }
    return work_j;
}

void set_body_velocity(World& w, std::uint32_t i, Vec2 velocity_m_s, double angular_velocity_rad_s) {
    Bodies& b = w.bodies;
    auto kinetic_j = [&] {
        const Vec2 v = b.velocity_m_s[i];
        return 0.5 * b.mass_kg[i] * (v.x * v.x + v.y * v.y) +
               0.5 * b.inertia_kg_m2[i] * b.angular_velocity_rad_s[i] * b.angular_velocity_rad_s[i];
    };
    const double before_j = kinetic_j();
    b.velocity_m_s[i] = velocity_m_s;
    b.angular_velocity_rad_s[i] = angular_velocity_rad_s;
    w.energy.external_work_j += kinetic_j() - before_j;
}

}  // namespace blockdem
