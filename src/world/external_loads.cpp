#include "world/external_loads.hpp"

#include "world/world.hpp"

namespace blockdem {

void set_external_load(World& w, std::uint32_t i, Vec2 force_n, double torque_n_m) {
    ExternalLoads& loads = w.external_loads;
    if (!loads.any()) {
        loads.force_n.assign(w.bodies.size(), Vec2{});
        loads.torque_n_m.assign(w.bodies.size(), 0.0);
    }
    loads.force_n[i] = force_n;
    loads.torque_n_m[i] = torque_n_m;
}

void clear_external_loads(World& w) {
    w.external_loads.force_n.clear();
    w.external_loads.torque_n_m.clear();
}

void add_external_load(World& w, std::size_t i) {
    // (Only dynamic bodies move; a static body's sums are not used for its motion.)
    w.bodies.force_n[i] += w.external_loads.force_n[i];
    w.bodies.torque_n_m[i] += w.external_loads.torque_n_m[i];
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
