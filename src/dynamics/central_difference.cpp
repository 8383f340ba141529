#include "dynamics/central_difference.hpp"

#include "world/parallel.hpp"

namespace blockdem {

void place_driven_bodies(World& w, double t_s) {
    Bodies& b = w.bodies;
    const MotionSample h = sample(w.table_motion.horizontal, t_s);
    const MotionSample v = sample(w.table_motion.vertical, t_s);
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (b.kind[i] != BodyKind::driven) continue;
        b.position_m[i] = b.initial_position_m[i] + Vec2{h.displacement_m, v.displacement_m};
        b.velocity_m_s[i] = {h.velocity_m_s, v.velocity_m_s};
        b.velocity_at_t_m_s[i] = b.velocity_m_s[i];
        b.acceleration_m_s2[i] = {h.acceleration_m_s2, v.acceleration_m_s2};
    }
}

void set_driven_velocities(World& w) {
    Bodies& b = w.bodies;
    const MotionSample h = sample(w.table_motion.horizontal, w.time_s);
    const MotionSample v = sample(w.table_motion.vertical, w.time_s);
    for (std::uint32_t i : w.driven_bodies) {
        b.acceleration_m_s2[i] = {h.acceleration_m_s2, v.acceleration_m_s2};
        b.velocity_at_t_m_s[i] = {h.velocity_m_s, v.velocity_m_s};
    }
}

double update_positions(World& w) {
    Bodies& b = w.bodies;
    const double dt = w.dt_s;
    const double t_next = w.time_s + dt;
    const Vec2 next_table{sample(w.table_motion.horizontal, t_next).displacement_m,
                          sample(w.table_motion.vertical, t_next).displacement_m};
    const auto n = static_cast<std::ptrdiff_t>(b.size());
    parallel_for(n, [&](std::ptrdiff_t i) {
        if (b.kind[i] != BodyKind::dynamic) return;
        b.position_m[i] += dt * b.velocity_m_s[i];
        b.rotation_rad[i] += dt * b.angular_velocity_rad_s[i];
    });
    // Driven bodies in id order (a few): the table work is summed serially, deterministic.
    double table_work_j = 0.0;
    for (std::uint32_t i : w.driven_bodies) {
        const Vec2 next = b.initial_position_m[i] + next_table;
        const Vec2 moved = next - b.position_m[i];
        // The contacts push on the table with force_n (at t); the table does work -force . dx on
        // them. The scheme's own energy identity, m/2 (v(t+dt/2)^2 - v(t-dt/2)^2) =
        // F(t) . (x(t+dt) - x(t-dt)) / 2, pairs the force at t with the centred displacement, and
        // so must the table's work: the forward difference x(t+dt) - x(t) adds F a dt^2 / 2 a step,
        // which for a block sticking to a shaken table (F = m a) grows as m a^2 dt t / 4.
        const Vec2 previous = b.position_m[i] - dt * b.velocity_m_s[i];
        table_work_j -= dot(b.force_n[i], 0.5 * (next - previous));
        b.velocity_m_s[i] = (1.0 / dt) * moved;
        b.position_m[i] = next;
    }
    return table_work_j;
}

}  // namespace blockdem
