#pragma once
// Rotation of a rigid body in 3-D, in the body frame, by the central-difference scheme.
//
// The 2-D scheme (dynamics/central_difference.hpp) kicks the velocity by a(t) dt and drifts the
// position by v(t + dt/2) dt. In 3-D the kick is the same on the world-frame angular momentum,
// L(t + dt/2) = L(t - dt/2) + T(t) dt, and the drift turns the body over dt at the constant L by
// the exact rotation of omega dt, omega being the body-frame angular velocity over the step.
// Euler's gyroscopic term lives in that drift: seen from the body, L turns while the body turns.
//
// Which omega: the one of the mean of the body-frame angular momenta at the two ends of the step,
//   omega = I^-1 (L_start + L_end) / 2,   L_end = exp(omega dt)^T L_start,
// solved by fixed-point iteration (it contracts by about |omega| dt a round). Why: L_end is
// L_start turned exactly about omega, so L_end - L_start is perpendicular to omega and the
// kinetic energy changes by (L_end - L_start) . omega = 0; the body turns by exactly the inverse
// rotation, so the world-frame L is unchanged. Torque-free motion thus keeps both invariants to
// round-off (the implicit midpoint rule on Euler's equations with the exact rotation in place of
// the Cayley map), where an explicit gyroscopic term (omega(t) x I omega(t)) keeps neither. The
// cost: 4 to 7 rounds of a quaternion exp and two products a step (0.2 us at |omega| dt = 0.001);
// the rounds stop once the contraction bound puts the fixed point within round-off, which for a
// body nearly at rest (|omega| dt below 1e-8) is after one round, worked out by the turn's series.
#include <algorithm>

#include "dynamics/rigid_body_3d.hpp"
#include "geometry/packed_vec3.hpp"

namespace blockdem {

/// Turns orientation over dt_s [s] at the constant world-frame angular momentum [kg m^2/s] of a
/// body with the given inverse principal moments [1/(kg m^2)]; returns the body-frame angular
/// velocity [rad/s] it turned with. Throws SimulationError when the iteration does not converge
/// (|omega| dt of order one: a time step far above any stable one).
Vec3 free_rotation(Quaternion& orientation, Vec3 angular_momentum_kg_m2_s, Vec3 inverse_moments_1_kg_m2, double dt_s);
/// The same from the angular momentum in the body frame at the orientation now [kg m^2/s].
Vec3 free_rotation_of_body_momentum(Quaternion& orientation, Vec3 body_momentum_kg_m2_s, Vec3 inverse_moments_1_kg_m2,
                                    double dt_s);

/// The kick: velocity and angular momentum to t + dt/2 from the force and torque at t, and the
/// velocities at t (the mean of the two half steps). starting: the stored velocities are those
/// at t (the initial state), so the scheme starts with a half step, as in 2-D. Returns the
/// kinetic energy at t [J] (kinetic_energy's, to round-off, from the body-frame angular velocity
/// the kick has at hand).
double update_velocity_3d(RigidBody3d& b, double dt_s, bool starting = false);
/// The same with the matrix of b's orientation at t already at hand (the 3-D step's pose):
/// two products by a matrix instead of two turns by the quaternion. Defined here so that the
/// step's kick loop inlines it (called, a body's kick cost about 20 instructions more).
inline double update_velocity_3d(RigidBody3d& b, const Matrix3d& rotation, double dt_s, bool starting) {
    // In two lanes (geometry/packed_vec3.hpp): each lane rounds as the Vec3 expression, the same bits.
    const PackedVec3 force_n = load(b.force_n);
    const PackedVec3 torque_n_m = load(b.torque_n_m);
    const PackedVec3 a = (1.0 / b.mass_kg) * force_n;
    PackedVec3 v_old = load(b.velocity_m_s);
    PackedVec3 l_old = load(b.angular_momentum_kg_m2_s);
    if (starting) {
        // The stored velocities are at t: back to t - dt/2 by half a kick.
        v_old = v_old - (0.5 * dt_s) * a;
        l_old = l_old - (0.5 * dt_s) * torque_n_m;
    }
    const PackedVec3 v_new = v_old + dt_s * a;
    const PackedVec3 l_new = l_old + dt_s * torque_n_m;
    const PackedVec3 v_at_t = 0.5 * (v_old + v_new);
    store(v_new, &b.velocity_m_s);
    store(l_new, &b.angular_momentum_kg_m2_s);
    store(v_at_t, &b.velocity_at_t_m_s);
    // The angular velocity at t from the angular momentum at t at the orientation at t.
    const PackedVec3 l_at_t = 0.5 * (l_old + l_new);
    const PackedVec3 omega_body = hadamard(load(b.inverse_moments_1_kg_m2), transpose_times(rotation, l_at_t));
    store(packed(rotation) * omega_body, &b.angular_velocity_at_t_rad_s);
    return 0.5 * b.mass_kg * dot(v_at_t, v_at_t) +
           0.5 * dot(omega_body, hadamard(load(b.principal_moments_kg_m2), omega_body));
}

/// The drift: position and orientation to t + dt from the half-step velocities.
void update_position_3d(RigidBody3d& b, double dt_s);

/// Throws SimulationError: the rotation over one step did not converge at |omega| dt = angle_rad.
[[noreturn]] void throw_rotation_not_converged(double angle_rad);

namespace rotation_detail {

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

// free_rotation_of_body_momentum's work. In the header so that the 3-D step's drift loop inlines
// update_position_3d with the pose's matrix: called, the body's call and its vectors through memory
// cost about 20 instructions a body.
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
        if (round == max_rounds) throw_rotation_not_converged(length(omega) * dt_s);
    }
    orientation = renormalized(orientation * turn_of(dt_s * omega));
    return omega;
}

}  // namespace rotation_detail

/// The same with the matrix of b's orientation before the drift at hand (the 3-D step's pose).
/// Inline for the step's drift loop (see turn_at_constant_momentum).
[[gnu::always_inline]] inline void update_position_3d(RigidBody3d& b, const Matrix3d& rotation, double dt_s) {
    b.position_m += dt_s * b.velocity_m_s;
    b.angular_velocity_body_rad_s = rotation_detail::turn_at_constant_momentum(
        b.orientation, transpose_times(rotation, b.angular_momentum_kg_m2_s), b.inverse_moments_1_kg_m2, dt_s);
}

}  // namespace blockdem
