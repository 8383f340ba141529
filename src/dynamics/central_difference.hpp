#pragma once
// Time integration (Cundall's explicit central-difference scheme, second order):
//   v(t + dt/2) = v(t - dt/2) + a(t) dt,    x(t + dt) = x(t) + v(t + dt/2) dt,
// for translation and rotation of dynamic bodies, split in its two halves so that the state at
// t (positions, accelerations, and velocities averaged to t) can be recorded between them.
// Driven bodies are placed exactly where the table motion puts them at t + dt; their half-step
// velocity is the displacement difference over dt, so that the slip a block on the table sees
// is the table's exact displacement.
#include "world/world.hpp"

namespace blockdem {

/// Driven bodies' acceleration and velocity at t, from the table motion.
void set_driven_velocities(World& w);

/// Body i (if dynamic): acceleration at t from its force, velocity to t + dt/2 and the mean of
/// the two half steps (the velocity at t). Touches only body i.
/// starting: the stored velocity is the one at t (the given initial state), not at t - dt/2.
/// The scheme then starts with a half step, v(dt/2) = v(0) + a(0) dt/2, as a leapfrog must:
/// taking v(0) for v(-dt/2) would start every body a dt/2 late, and the kinetic energy the
/// run reports at t = 0 would differ from the initial state's by m (a dt)^2 / 8.
inline void update_body_velocity(Bodies& b, std::size_t i, double dt_s, bool starting = false) {
    if (b.kind[i] != BodyKind::dynamic) return;
    const Vec2 a = b.inv_mass_1_kg[i] * b.force_n[i];
    const double alpha = b.inv_inertia_1_kg_m2[i] * b.torque_n_m[i];
    const double back_s = starting ? 0.5 * dt_s : 0.0;
    const Vec2 v_old = b.velocity_m_s[i] - back_s * a;
    const double w_old = b.angular_velocity_rad_s[i] - back_s * alpha;
    b.acceleration_m_s2[i] = a;
    b.angular_acceleration_rad_s2[i] = alpha;
    b.velocity_m_s[i] = v_old + dt_s * a;
    b.angular_velocity_rad_s[i] = w_old + dt_s * alpha;
    b.velocity_at_t_m_s[i] = 0.5 * (v_old + b.velocity_m_s[i]);
    b.angular_velocity_at_t_rad_s[i] = 0.5 * (w_old + b.angular_velocity_rad_s[i]);
}


/// Positions to t + dt; returns the work [J] that driven bodies did on the rest in this step.
double update_positions(World& w);

/// Places driven bodies at their prescribed position and velocity for time t_s (used at t = 0).
void place_driven_bodies(World& w, double t_s);

}  // namespace blockdem
