#pragma once
// A rigid convex polyhedron with 6 degrees of freedom: its shape in the principal frame, its mass
// properties, and its state in the central-difference scheme (docs/3d.md).
//
// The body frame is the principal frame at the centroid, so that the inertia tensor there is
// diagonal and Euler's equations take their simple form; `orientation` turns it into the world
// frame. Rotation is carried as the world-frame angular momentum at half steps, the rotational
// counterpart of the velocity at half steps of the 2-D scheme (dynamics/central_difference.hpp):
// a torque changes it, nothing else does, so a torque-free body keeps it to round-off.
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/polyhedron.hpp"
#include "geometry/quaternion.hpp"
#include "geometry/vec3.hpp"

namespace blockdem {

/// A rigid body's shape and state. One a cache line, its state from mass_kg on in the last four
/// lines of its six: the step's passes over the bodies (pose, kick, drift) read and write those
/// fields, and a vector's block 16 bytes off a line with the mass before the principal moments
/// spread them over five or six (callgrind's simulated misses of the three passes: -11 %).
struct alignas(64) RigidBody3d {
    std::string name;
    Polyhedron shape;                  ///< vertices [m] in the body (principal) frame, about the centroid
    Vec3 principal_moments_kg_m2;      ///< [kg m^2] ascending, about the body axes
    double mass_kg = 0.0;              ///< [kg]
    Vec3 inverse_moments_1_kg_m2;      ///< [1/(kg m^2)] the principal moments' inverses

    Vec3 position_m;                   ///< [m] centroid at t
    Quaternion orientation;            ///< body frame to world at t
    Vec3 velocity_m_s;                 ///< [m/s] at t - dt/2 before the step, t + dt/2 after
    Vec3 angular_momentum_kg_m2_s;     ///< [kg m^2/s] about the centroid, world frame, likewise
    Vec3 angular_velocity_body_rad_s;  ///< [rad/s] body frame, over the last step (the one that turned it)
    Vec3 velocity_at_t_m_s;            ///< [m/s] at t (mean of the two half steps): for output
    Vec3 angular_velocity_at_t_rad_s;  ///< [rad/s] world frame at t: for output and the energy
    Vec3 force_n;                      ///< [N] total force at t, world frame
    Vec3 torque_n_m;                   ///< [N m] total torque about the centroid at t, world frame
};

/// A body of the given density [kg/m^3] whose vertices [m] are listed in the world frame at
/// t = 0: their hull is found and checked, the centroid and principal axes become the body
/// frame, and the state starts at rest. Throws ModelError naming the body when the vertices are
/// not a convex polyhedron (geometry/polyhedron.hpp says which vertex and why) or the density is
/// not positive.
RigidBody3d make_rigid_body_3d(const std::string& name, const std::vector<Vec3>& vertices_m, double density_kg_m3);

/// The same with the faces as listed (vertex indices counter-clockwise seen from outside), each
/// checked against the hull: an inverted, misordered, extra or missing face is refused with the
/// body and the face named.
RigidBody3d make_rigid_body_3d(const std::string& name, const std::vector<Vec3>& vertices_m,
                               const std::vector<std::vector<std::size_t>>& faces, double density_kg_m3);

/// The world-frame vertex i of the body now [m].
inline Vec3 world_vertex(const RigidBody3d& b, std::size_t i) {
    return b.position_m + rotate(b.orientation, b.shape.vertices_m[i]);
}

/// Sets the body's velocity and angular velocity [rad/s, world frame] at t (the initial state;
/// the first update_velocity_3d must then be called with starting = true).
void set_initial_velocity(RigidBody3d& b, Vec3 velocity_m_s, Vec3 angular_velocity_world_rad_s);

/// The world-frame angular momentum about the centroid [kg m^2/s] of an angular velocity [rad/s]
/// (world frame) at the body's orientation now.
Vec3 angular_momentum_of(const RigidBody3d& b, Vec3 angular_velocity_world_rad_s);

/// Kinetic energy at t [J]: translation plus rotation, from the velocities at t.
double kinetic_energy(const RigidBody3d& b);

}  // namespace blockdem
