#include "dynamics/rigid_rotation_3d.hpp"

#include <fmt/format.h>

#include "world/simulation_error.hpp"

namespace blockdem {

[[noreturn]] void throw_rotation_not_converged(double angle_rad) {
    throw SimulationError(fmt::format(
        "the rotation over one step did not converge (|omega| dt = {:g} rad): the time step is far too long", angle_rad));
}

Vec3 free_rotation(Quaternion& orientation, Vec3 angular_momentum_kg_m2_s, Vec3 inverse_moments_1_kg_m2, double dt_s) {
    return free_rotation_of_body_momentum(orientation, rotate_inverse(orientation, angular_momentum_kg_m2_s),
                                          inverse_moments_1_kg_m2, dt_s);
}

Vec3 free_rotation_of_body_momentum(Quaternion& orientation, Vec3 start, Vec3 inverse_moments_1_kg_m2, double dt_s) {
    return rotation_detail::turn_at_constant_momentum(orientation, start, inverse_moments_1_kg_m2, dt_s);
}

double update_velocity_3d(RigidBody3d& b, double dt_s, bool starting) {
    return update_velocity_3d(b, rotation_matrix_by_products(b.orientation), dt_s, starting);
}

void update_position_3d(RigidBody3d& b, double dt_s) {
    b.position_m += dt_s * b.velocity_m_s;
    b.angular_velocity_body_rad_s =
        free_rotation(b.orientation, b.angular_momentum_kg_m2_s, b.inverse_moments_1_kg_m2, dt_s);
}

}  // namespace blockdem
