// A caller's loads on 3-D bodies (world/external_loads_3d.hpp, applied in world/step_3d.cpp)
// against the closed forms: a box on a fixed slab pushed above friction accelerates at
// (F - mu m g) / m and below it stays put; a torque about a tilted axis turns a box in the air at
// I^-1 T; a held velocity is kept exactly with the holding force that of friction; the loads'
// work closes the energy ledger, and the result is the same bytes on 1 and 2 threads.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "dynamics/rigid_body_3d.hpp"
#include "geometry/quaternion.hpp"
#include "geometry/vec3.hpp"
#include "scenes/brick_wall_3d.hpp"
#include "validation/validation_constants.hpp"
#include "world/external_loads_3d.hpp"
#include "world/step_3d.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace blockdem {
namespace {

using validation::g;
constexpr double mass_kg = 16.0;    // [kg] a 0.4 x 0.4 x 0.1 m box
constexpr double slab_mu = 0.5;     // the box's friction coefficient on the slab

// A flat box (low, so that a push at its centroid slides it rather than tips it) resting on a
// fixed slab, settled for 0.02 s.
World3d box_on_slab() {
    World3d w;
    w.contact = ContactParameters{.kn_N_m = 1e8, .ks_N_m = 1e8, .mu = slab_mu, .h_n = 0.3, .h_s = 0.3};
    w.dt_s = 2e-5;
    add_body(w, make_rigid_body_3d("slab", box_vertices({4.0, 4.0, 0.2}, {0.0, 0.0, -0.1}), 1000.0), BodyKind3d::fixed);
    add_body(w, make_rigid_body_3d("box", box_vertices({0.4, 0.4, 0.1}, {0.0, 0.0, 0.05}), mass_kg / 0.016),
             BodyKind3d::dynamic);
    for (int i = 0; i < 1000; ++i) step_3d(w);
    return w;
}

TEST(ExternalLoads3d, APushAboveFrictionAcceleratesTheBoxAtFMinusMuMgOverM) {
    World3d w = box_on_slab();
    const double force_n = 1.5 * slab_mu * mass_kg * g;
    set_external_load(w, 1, {0.0, force_n, 0.0}, {});
    for (int i = 0; i < 1000; ++i) step_3d(w);  // the shear springs load up to the cap first
    const double t0_s = w.time_s;
    const double v0_m_s = w.bodies[1].velocity_at_t_m_s.y;
    for (int i = 0; i < 5000; ++i) step_3d(w);
    const double acceleration_m_s2 = (w.bodies[1].velocity_at_t_m_s.y - v0_m_s) / (w.time_s - t0_s);
    // Closed form; 0.5 %: the settling's ringing of the normal springs moves the normal force by
    // less (measured 1e-13 relative).
    EXPECT_NEAR(acceleration_m_s2, (force_n - slab_mu * mass_kg * g) / mass_kg, 5e-3 * (force_n / mass_kg - slab_mu * g));
    EXPECT_NEAR(w.bodies[1].velocity_at_t_m_s.x, 0.0, 1e-9);
    EXPECT_GT(w.ledger.external_work_j, 0.0);
    EXPECT_LT(w.ledger.balance_error(), 1e-3);
}

TEST(ExternalLoads3d, APushBelowFrictionLeavesTheBoxWhereItIs) {
    World3d w = box_on_slab();
    const Vec3 start_m = w.bodies[1].position_m;
    set_external_load(w, 1, {0.3 * slab_mu * mass_kg * g, 0.4 * slab_mu * mass_kg * g, 0.0}, {});
    for (int i = 0; i < 5000; ++i) step_3d(w);
    // The shear springs' elastic give, F / (4 ks) ~ 1e-7 m, and nothing more.
    EXPECT_LT(length(w.bodies[1].position_m - start_m), 1e-6);
    EXPECT_LT(w.ledger.balance_error(), 1e-3);
}

TEST(ExternalLoads3d, ATorqueTurnsAFreeBoxAtTheInverseInertiaTimesIt) {
    // In the air without gravity, from rest: over a short time (the turn stays small, 0.01 rad)
    // the angular velocity is I^-1 T t with I the world-frame inertia at the start.
    World3d w;
    w.gravity_m_s2 = 0.0;
    w.dt_s = 1e-5;
    const Quaternion turn = from_rotation_vector({0.3, -0.2, 0.5});
    add_body(w, make_rigid_body_3d("box", box_vertices({0.4, 0.3, 0.1}, {0.0, 0.0, 1.0}, turn), 1000.0), BodyKind3d::dynamic);
    const RigidBody3d& b = w.bodies[0];
    const Vec3 torque_n_m{0.2, -0.1, 0.3};
    set_external_load(w, 0, {}, torque_n_m);
    const Vec3 expected_per_s = rotate(b.orientation, hadamard(b.inverse_moments_1_kg_m2, rotate_inverse(b.orientation, torque_n_m)));
    for (int i = 0; i < 200; ++i) step_3d(w);
    step_begin(w);  // the ledger at t, as the run loop reads it (the work is booked at the drift)
    // 1e-4: the inertia's turn and the gyroscopic term (omega x I omega) are second order in the
    // turn, some 1e-2 rad (measured 1.8e-6).
    EXPECT_LT(length(b.angular_velocity_at_t_rad_s - w.time_s * expected_per_s), 1e-4 * w.time_s * length(expected_per_s));
    // No force: the centroid stays; the ledger closes on the torque's work alone.
    EXPECT_LT(length(b.position_m - Vec3{0.0, 0.0, 1.0}), 1e-15);
    // With nothing else acting, the torque's work is the kinetic energy to round-off (measured 2e-15).
    EXPECT_LT(w.ledger.balance_error(), 1e-9);
}

TEST(ExternalLoads3d, AHeldVelocityIsKeptAndHeldByTheFrictionForce) {
    World3d w = box_on_slab();
    hold_body_velocity(w, 1, {0.2, 0.0, 0.0}, {});
    for (int i = 0; i < 2500; ++i) step_3d(w);
    EXPECT_NEAR(length(w.bodies[1].velocity_m_s - Vec3{0.2, 0.0, 0.0}), 0.0, 1e-12);
    // Steady sliding: the holding force is mu m g along the motion (measured 1e-10 relative).
    EXPECT_NEAR(w.external_loads.force_n[1].x, slab_mu * mass_kg * g, 1e-6 * slab_mu * mass_kg * g);
    // The jump to the held velocity leaves half a step's friction work unbooked, once (the ledger's
    // kinetic energy is at t, the jump at a half step): 1.6e-4 J of 0.8 J here.
    EXPECT_LT(w.ledger.balance_error(), 1e-3);
    release_body_velocity(w, 1);
    EXPECT_EQ(w.external_loads.held[1], 0);
    EXPECT_EQ(length(w.external_loads.force_n[1]), 0.0);
}

std::vector<unsigned char> body_bytes(const World3d& w) {
    std::vector<unsigned char> bytes(w.bodies.size() * 4 * sizeof(Vec3));
    unsigned char* out = bytes.data();
    for (const RigidBody3d& b : w.bodies)
        for (const Vec3* v : {&b.position_m, &b.velocity_m_s, &b.angular_momentum_kg_m2_s, &b.force_n}) {
            std::memcpy(out, v, sizeof(Vec3));
            out += sizeof(Vec3);
        }
    return bytes;
}

TEST(ExternalLoads3d, LoadsGiveTheSameBytesOnOneAndTwoThreads) {
#ifndef _OPENMP
    GTEST_SKIP() << "built without OpenMP";
#else
    scenes::BrickWall3dDef def;
    def.courses = 3;
    def.bricks_per_course = 8;
    std::vector<std::vector<unsigned char>> runs;
    const int threads_before = omp_get_max_threads();
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        World3d w = scenes::brick_wall_3d(def);
        const auto top = static_cast<std::uint32_t>(w.bodies.size() - 1);
        set_external_load(w, top, {0.0, 500.0, 0.0}, {0.0, 0.0, 20.0});
        hold_body_velocity(w, top - 3, {0.0, -0.05, 0.0}, {});
        for (int i = 0; i < 300; ++i) step_3d(w);
        step_begin(w);  // the ledger at t, as the run loop reads it (the work is booked at the drift)
        runs.push_back(body_bytes(w));
        // The wall settles from its placing meanwhile: without loads its ledger closes to 1.0e-3,
        // with them 1.5e-3 (the work is booked at the step's start force, first order in dt).
        EXPECT_LT(w.ledger.balance_error(), 2e-3);
    }
    omp_set_num_threads(threads_before);
    EXPECT_EQ(runs[0], runs[1]);
#endif
}

}  // namespace
}  // namespace blockdem
