#include "dynamics/rigid_rotation_3d.hpp"

#include <fmt/format.h>

#include "world/simulation_error.hpp"

namespace blockdem {

Vec3 free_rotation(Quaternion& orientation, Vec3 angular_momentum_kg_m2_s, Vec3 inverse_moments_1_kg_m2, double dt_s) {
    const Vec3 start = rotate_inverse(orientation, angular_momentum_kg_m2_s);
    Vec3 omega = hadamard(inverse_moments_1_kg_m2, start);
    constexpr int max_rounds = 60;
    for (int round = 0;; ++round) {
        const Vec3 end = rotate_inverse(from_rotation_vector(dt_s * omega), start);
        const Vec3 next = hadamard(inverse_moments_1_kg_m2, 0.5 * (start + end));
        const double change = length(next - omega);
        omega = next;
        // Round-off of a sum of order |omega|: the fixed point is reached.
        if (change <= 2e-15 * length(omega)) break;
        if (round == max_rounds)
            throw SimulationError(fmt::format(
                "the rotation over one step did not converge (|omega| dt = {:g} rad): the time step is far too long",
                length(omega) * dt_s));
    }
    orientation = normalized(orientation * from_rotation_vector(dt_s * omega));
    return omega;
}

void update_velocity_3d(RigidBody3d& b, double dt_s, bool starting) {
    const Vec3 a = (1.0 / b.mass_kg) * b.force_n;
    const double back_s = starting ? 0.5 * dt_s : 0.0;
    const Vec3 v_old = b.velocity_m_s - back_s * a;
    const Vec3 l_old = b.angular_momentum_kg_m2_s - back_s * b.torque_n_m;
    b.velocity_m_s = v_old + dt_s * a;
    b.angular_momentum_kg_m2_s = l_old + dt_s * b.torque_n_m;
    b.velocity_at_t_m_s = 0.5 * (v_old + b.velocity_m_s);
    // The angular velocity at t from the angular momentum at t at the orientation at t.
    const Vec3 l_at_t = 0.5 * (l_old + b.angular_momentum_kg_m2_s);
    const Vec3 omega_body = hadamard(b.inverse_moments_1_kg_m2, rotate_inverse(b.orientation, l_at_t));
    b.angular_velocity_at_t_rad_s = rotate(b.orientation, omega_body);
}

void update_position_3d(RigidBody3d& b, double dt_s) {
    b.position_m += dt_s * b.velocity_m_s;
    b.angular_velocity_body_rad_s =
        free_rotation(b.orientation, b.angular_momentum_kg_m2_s, b.inverse_moments_1_kg_m2, dt_s);
}

}  // namespace blockdem
