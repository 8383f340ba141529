// The 3-D central-difference step (dynamics/rigid_rotation_3d.hpp) under a constant force and
// torque: the leapfrog is exact for constant accelerations, so the state matches the closed form
// to round-off.
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/rigid_rotation_3d.hpp"
#include "world/simulation_error.hpp"

namespace blockdem {
namespace {

TEST(RigidRotation3d, ConstantTorqueAboutAPrincipalAxis) {
    RigidBody3d b = make_rigid_body_3d(
        "block", box_vertices({0.4, 0.3, 0.2}, {1, 2, 3}, from_rotation_vector({0.2, 0.5, -0.1})), 2500.0);
    const Quaternion start = b.orientation;
    const Vec3 axis = rotate(b.orientation, {0, 1, 0});  // the intermediate axis, in the world
    const double torque_n_m = 3.0, force_n = 5.0, dt_s = 1e-3;
    const int steps = 2000;
    for (int n = 0; n < steps; ++n) {
        b.torque_n_m = torque_n_m * axis;
        b.force_n = {0, 0, force_n};
        update_velocity_3d(b, dt_s, n == 0);
        update_position_3d(b, dt_s);
    }
    const double t = steps * dt_s;
    // About a principal axis there is no gyroscopic torque: theta = T t^2 / (2 I).
    const double angle = torque_n_m * t * t / (2.0 * b.principal_moments_kg_m2.y);
    const Quaternion expected = from_rotation_vector(angle * axis) * start;
    EXPECT_NEAR(std::abs(expected.w * b.orientation.w + expected.x * b.orientation.x + expected.y * b.orientation.y +
                         expected.z * b.orientation.z),
                1.0, 1e-12);
    EXPECT_NEAR(b.position_m.z - 3.0, force_n * t * t / (2.0 * b.mass_kg), 1e-12);
    // Half-step angular velocity in the body frame: T (t + dt/2) / I about y only.
    EXPECT_NEAR(b.angular_velocity_body_rad_s.y, torque_n_m * (t - 0.5 * dt_s) / b.principal_moments_kg_m2.y, 1e-10);
    EXPECT_NEAR(std::abs(b.angular_velocity_body_rad_s.x) + std::abs(b.angular_velocity_body_rad_s.z), 0.0, 1e-12);
}

TEST(RigidRotation3d, FarTooLongAStepIsRefused) {
    RigidBody3d b = make_rigid_body_3d("block", box_vertices({0.3, 0.2, 0.1}, {}), 2500.0);
    set_initial_velocity(b, {}, rotate(b.orientation, {0.0, 300.0, 30.0}));
    update_velocity_3d(b, 0.1, true);
    EXPECT_THROW(update_position_3d(b, 0.1), SimulationError);
}

TEST(RigidRotation3d, RotationVectorRoundTrip) {
    for (Vec3 v : {Vec3{0.1, -0.2, 0.3}, Vec3{1e-10, 0, 2e-10}, Vec3{0, 3.0, 0}}) {
        const Vec3 back = rotation_vector(from_rotation_vector(v));
        EXPECT_NEAR(length(back - v), 0.0, 1e-15);
    }
}

}  // namespace
}  // namespace blockdem
