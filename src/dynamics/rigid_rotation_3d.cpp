#include "dynamics/rigid_rotation_3d.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "world/simulation_error.hpp"

namespace blockdem {

namespace {

// Below this squared angle [rad^2] a turn is worked out by its series: R(t) v = v + t x v +
// t x (t x v) / 2 leaves out (|t|^2/6) |t x v| + (|t|^4/24) |v|, at most 1.4e-18 |v| for
// |t| <= 2e-6, a hundredth of the round-off of v's own components; the quaternion's series
// below leave out |t|^4/384 and |t|^5/3840 (1e-25). At rest on a wall a brick turns about 1e-8 rad
// a step: the sine, the cosine and the square root of the exact turn are then not needed.
constexpr double series_angle2_rad2 = 4e-12;

// v turned by minus the rotation vector t [rad] (the transpose of R(t) times v).
[[gnu::always_inline]] inline Vec3 turned_back(Vec3 t, Vec3 v) {
    if (dot(t, t) <= series_angle2_rad2) {
        const Vec3 tv = cross(t, v);
        return v - tv + 0.5 * cross(t, tv);
    }
    return rotate_inverse(from_rotation_vector(t), v);
}

// exp of the rotation vector t [rad], not yet of unit length when small (the caller normalises).
[[gnu::always_inline]] inline Quaternion turn_of(Vec3 t) {
    const double angle2 = dot(t, t);
    if (angle2 > series_angle2_rad2) return from_rotation_vector(t);
    // Products by the series' constants, not divisions (a division is the slowest operation of the drift).
    const double half = 0.5 - angle2 * (1.0 / 48.0);
    return {1.0 - angle2 * 0.125, half * t.x, half * t.y, half * t.z};
}

[[noreturn]] void throw_not_converged(double angle_rad) {
    throw SimulationError(fmt::format(
        "the rotation over one step did not converge (|omega| dt = {:g} rad): the time step is far too long", angle_rad));
}

// free_rotation_of_body_momentum's work, inlined into the drift of the 3-D step (update_position_3d
// with the pose's matrix): called, its vectors went through memory, about 20 instructions a body.
[[gnu::always_inline]] inline Vec3 turn_at_constant_momentum(Quaternion& orientation, Vec3 start,
                                                             Vec3 inverse_moments_1_kg_m2, double dt_s) {
    Vec3 omega = hadamard(inverse_moments_1_kg_m2, start);
    // How fast the rounds contract: turning a vector L by an angle a moves it by at most |L| a,
    // so a round moves omega by at most kappa = max(1/I) |L| dt / 2 times the last change. Once a
    // round changed omega by c, the fixed point is within kappa c / (1 - kappa) <= 2 kappa c of
    // it (kappa <= 1/2): below 2^-53 |omega|, the rounds left would only move round-off. A brick
    // at rest (kappa about 1e-8) then takes one round where the test below alone takes three.
    const double largest_inverse = std::max({inverse_moments_1_kg_m2.x, inverse_moments_1_kg_m2.y,
                                             inverse_moments_1_kg_m2.z});
    const double kappa2 = 0.25 * dt_s * dt_s * largest_inverse * largest_inverse * dot(start, start);
    constexpr double unit_round2 = 0x1p-106;  // (2^-53)^2
    constexpr int max_rounds = 60;
    for (int round = 0;; ++round) {
        const Vec3 end = turned_back(dt_s * omega, start);
        const Vec3 next = hadamard(inverse_moments_1_kg_m2, 0.5 * (start + end));
        const Vec3 change = next - omega;
        const double change2 = dot(change, change);
        omega = next;
        const double omega2 = dot(omega, omega);
        // Round-off of a sum of order |omega| (2e-15 |omega|, squared): the fixed point is reached.
        if (change2 <= 4e-30 * omega2) break;
        if (kappa2 <= 0.25 && 4.0 * kappa2 * change2 <= unit_round2 * omega2) break;
        if (round == max_rounds) throw_not_converged(length(omega) * dt_s);
    }
    orientation = renormalized(orientation * turn_of(dt_s * omega));
    return omega;
}

}  // namespace

Vec3 free_rotation(Quaternion& orientation, Vec3 angular_momentum_kg_m2_s, Vec3 inverse_moments_1_kg_m2, double dt_s) {
    return free_rotation_of_body_momentum(orientation, rotate_inverse(orientation, angular_momentum_kg_m2_s),
                                          inverse_moments_1_kg_m2, dt_s);
}

Vec3 free_rotation_of_body_momentum(Quaternion& orientation, Vec3 start, Vec3 inverse_moments_1_kg_m2, double dt_s) {
    return turn_at_constant_momentum(orientation, start, inverse_moments_1_kg_m2, dt_s);
}

double update_velocity_3d(RigidBody3d& b, double dt_s, bool starting) {
    return update_velocity_3d(b, rotation_matrix_by_products(b.orientation), dt_s, starting);
}

void update_position_3d(RigidBody3d& b, const Matrix3d& rotation, double dt_s) {
    b.position_m += dt_s * b.velocity_m_s;
    b.angular_velocity_body_rad_s = turn_at_constant_momentum(
        b.orientation, transpose_times(rotation, b.angular_momentum_kg_m2_s), b.inverse_moments_1_kg_m2, dt_s);
}

void update_position_3d(RigidBody3d& b, double dt_s) {
    b.position_m += dt_s * b.velocity_m_s;
    b.angular_velocity_body_rad_s =
        free_rotation(b.orientation, b.angular_momentum_kg_m2_s, b.inverse_moments_1_kg_m2, dt_s);
}

}  // namespace blockdem
