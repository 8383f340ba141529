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
#include "dynamics/rigid_body_3d.hpp"

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
    const Vec3 a = (1.0 / b.mass_kg) * b.force_n;
    Vec3 v_old = b.velocity_m_s;
    Vec3 l_old = b.angular_momentum_kg_m2_s;
    if (starting) {
        // The stored velocities are at t: back to t - dt/2 by half a kick.
        v_old -= (0.5 * dt_s) * a;
        l_old -= (0.5 * dt_s) * b.torque_n_m;
    }
    b.velocity_m_s = v_old + dt_s * a;
    b.angular_momentum_kg_m2_s = l_old + dt_s * b.torque_n_m;
    b.velocity_at_t_m_s = 0.5 * (v_old + b.velocity_m_s);
    // The angular velocity at t from the angular momentum at t at the orientation at t.
    const Vec3 l_at_t = 0.5 * (l_old + b.angular_momentum_kg_m2_s);
    const Vec3 omega_body = hadamard(b.inverse_moments_1_kg_m2, transpose_times(rotation, l_at_t));
    b.angular_velocity_at_t_rad_s = rotation * omega_body;
    return 0.5 * b.mass_kg * dot(b.velocity_at_t_m_s, b.velocity_at_t_m_s) +
           0.5 * dot(omega_body, hadamard(b.principal_moments_kg_m2, omega_body));
}

/// The drift: position and orientation to t + dt from the half-step velocities.
void update_position_3d(RigidBody3d& b, double dt_s);
/// The same with the matrix of b's orientation before the drift at hand (the 3-D step's pose).
void update_position_3d(RigidBody3d& b, const Matrix3d& rotation, double dt_s);

}  // namespace blockdem
