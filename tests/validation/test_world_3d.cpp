// Many 3-D bodies in one world (world/world_3d.hpp, world/step_3d.hpp): polyhedra on polyhedra
// through the separating-axis narrow phase (geometry/polyhedron_contact_3d.hpp), against the
// closed forms of the 2-D suite and the half-space contact already validated
// (tests/validation/test_table_contact_3d.cpp): a box resting on a fixed box as on the half-space,
// a column of three 32-sided drums standing still with the ledger closed, a flat drop rebounding
// with the requested e, sliding on a driven box against Newmark, and an edge-on-edge collision
// keeping the momenta.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <numbers>
#include <vector>

#include "analysis/rigid_plastic_sliding.hpp"
#include "dynamics/critical_time_step_3d.hpp"
#include "laws/restitution.hpp"
#include "support/table_run_3d.hpp"
#include "scenes/brick_wall_3d.hpp"
#include "scenes/s3d_wall_3d.hpp"
#include "validation/validation_constants.hpp"
#include "world/step_3d.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace blockdem {
namespace {

using validation::g;

// A box of the given size [m], centre [m], mass [kg] and turn.
RigidBody3d box(const char* name, Vec3 lengths_m, Vec3 center_m, double mass_kg, Quaternion turn = {}) {
    return make_rigid_body_3d(name, box_vertices(lengths_m, center_m, turn),
                              mass_kg / (lengths_m.x * lengths_m.y * lengths_m.z));
}

// A 2 x 2 x 0.2 m slab with its top at z = 0, of the given kind.
std::uint32_t add_slab(World3d& w, BodyKind3d kind) {
    return add_body(w, box("slab", {2.0, 2.0, 0.2}, {0.0, 0.0, -0.1}, 800.0), kind);
}

TEST(World3d, BoxRestsOnAFixedBoxAsOnTheHalfSpace) {
    // The polyhedron-polyhedron contact reduces to the half-space one when the lower body's top
    // face is larger than the upper body's base: the same four corners, the same law and mass
    // share. Both runs start touching at rest and settle to the static overlap m g / (4 kn).
    const ContactParameters contact{.kn_N_m = 1e6, .ks_N_m = 1e6, .mu = 0.6, .h_n = damping_ratio_rebound(0.5),
                                    .h_s = 0.5};
    const RigidBody3d upper = box("box", {0.5, 0.2, 0.2}, {0.1, -0.2, 0.1}, 20.0, from_rotation_vector({0, 0, 0.4}));
    World3d w;
    w.contact = contact;
    add_slab(w, BodyKind3d::fixed);
    add_body(w, upper, BodyKind3d::dynamic);
    testing::TableRun3d half_space = testing::table_run(upper, contact);
    double worst_difference_m = 0.0;
    while (w.time_s < 0.5 - 0.5 * w.dt_s) {
        step_3d(w);
        half_space.step();
        worst_difference_m = std::max(worst_difference_m, length(w.bodies[1].position_m - half_space.body.position_m));
        // (At the start the corners touch at zero overlap: some count by round-off, then all four.)
        if (w.steps > 10) ASSERT_EQ(w.contacts.size(), 4u) << "at t = " << w.time_s;
    }
    // Every point a corner of the box's base on the slab's top face.
    for (const ContactPoint3d& c : w.contacts) {
        EXPECT_EQ(feature_kind(c.key.feature_a), FeatureKind3d::face);
        EXPECT_EQ(feature_kind(c.key.feature_b), FeatureKind3d::vertex);
    }
    const double static_overlap_m = 20.0 * g / (4.0 * 1e6);
    const double overlap_m = 0.1 - w.bodies[1].position_m.z;
    // The two runs differ only by where the force acts: midway between the surfaces here, at the
    // corner there (half an overlap, 2.5e-5 m, along the normal); measured below 1e-12 m.
    EXPECT_LT(worst_difference_m, 1e-9);
    // Settled: after 0.5 s (some 35 periods at h_n = 0.22) the overlap is the static one to 1e-6.
    EXPECT_NEAR(overlap_m, static_overlap_m, 1e-6 * static_overlap_m);
    EXPECT_LT(length(w.bodies[1].velocity_at_t_m_s), 1e-6);
    // The ledger is the half-space's to round-off; both carry the scheme's second-order error of
    // a settling from rest (omega dt = 0.045 here): 1.7e-4.
    EXPECT_NEAR(w.ledger.balance_error(), half_space.ledger.balance_error(), 1e-9);
    EXPECT_LT(w.ledger.balance_error(), 1e-3);
    std::printf("box on fixed box: overlap %.6e m (m g / 4 kn = %.6e), largest difference from the half-space %.2e m, "
                "energy balance error %.2e (half-space %.2e)\n",
                overlap_m, static_overlap_m, worst_difference_m, w.ledger.balance_error(),
                half_space.ledger.balance_error());
}

// A 32-sided drum of radius 0.3 m and height 0.4 m standing on z = base_z_m.
RigidBody3d drum(const char* name, double base_z_m) {
    std::vector<Vec2> polygon;
    for (int k = 0; k < 32; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 32.0;
        polygon.push_back({0.3 * std::cos(a), 0.3 * std::sin(a)});
    }
    std::vector<Vec3> vertices = prism_vertices(polygon, 0.4);
    for (Vec3& v : vertices) v.z += base_z_m;
    return make_rigid_body_3d(name, vertices, 2600.0);
}

TEST(World3d, ThreeDrumColumnStandsAtRestWithTheLedgerClosed) {
    // Three drums on a fixed slab, each placed touching the one below: their faces coincide, so
    // every corner of each lower face is a point (32 each, none dropped or doubled by the
    // clipping), and the column settles into its springs and stays, straight and still.
    World3d w;
    w.contact = {.kn_N_m = 1e8, .ks_N_m = 1e8, .mu = 0.6, .h_n = damping_ratio_rebound(0.3), .h_s = 0.3};
    w.dt_s = 5e-5;
    add_slab(w, BodyKind3d::fixed);
    for (int k = 0; k < 3; ++k) add_body(w, drum("drum", 0.4 * k), BodyKind3d::dynamic);
    std::vector<Vec3> start;
    std::vector<Quaternion> start_turn;
    for (const RigidBody3d& b : w.bodies) {
        start.push_back(b.position_m);
        start_turn.push_back(b.orientation);
    }
    while (w.time_s < 0.3 - 0.5 * w.dt_s) {
        step_3d(w);
        // Placed at zero overlap: the points appear as the column sinks into its springs.
        if (w.time_s > 5e-3) ASSERT_EQ(w.contacts.size(), 96u) << "at t = " << w.time_s;
    }
    double drift_m = 0.0, turn_rad = 0.0, speed_m_s = 0.0;
    for (std::size_t i = 1; i < w.bodies.size(); ++i) {
        const Vec3 d = w.bodies[i].position_m - start[i];
        drift_m = std::max(drift_m, std::hypot(d.x, d.y));
        turn_rad = std::max(turn_rad, length(rotation_vector(w.bodies[i].orientation * conjugate(start_turn[i]))));
        speed_m_s = std::max(speed_m_s, length(w.bodies[i].velocity_at_t_m_s));
    }
    // Symmetric: nothing pushes sideways or turns; round-off only (measured below).
    EXPECT_LT(drift_m, 1e-12);
    EXPECT_LT(turn_rad, 1e-12);
    EXPECT_LT(speed_m_s, 1e-5);
    // The top drum sinks by the three interfaces' static overlaps, 3, 2 and 1 drums' weight on 32
    // points, each with kn times its corner's share: a 32-gon's corners turn by 2 pi / 32, so each
    // weighs 1/8 and a face carries 4 kn in all (geometry/corner_share_3d.hpp).
    const double drum_weight_n = w.bodies[1].mass_kg * g;
    const double sink_m = (3.0 + 2.0 + 1.0) * drum_weight_n / (4.0 * 1e8);
    EXPECT_NEAR(start[3].z - w.bodies[3].position_m.z, sink_m, 1e-3 * sink_m);
    // The ledger closes to the scheme's second-order error of the settling (the column's highest
    // mode has omega dt of about 0.1 with 4 kn a face): measured 6.0e-5 (4.8e-4 with a full kn a corner).
    EXPECT_LT(w.ledger.balance_error(), 1e-3);
    std::printf("drum column: 96 points, sideways drift %.2e m, turn %.2e rad, speed %.2e m/s, top sank %.4e m "
                "(springs in series %.4e), energy balance error %.2e\n",
                drift_m, turn_rad, speed_m_s, start[3].z - w.bodies[3].position_m.z, sink_m, w.ledger.balance_error());
}

// A 20 kg box 0.5 x 0.2 x 0.2 m falling flat at 1 m/s onto a fixed slab, 0.1 mm above it, no
// gravity, dt = 1e-6 s, with the given contact; stepped until it has touched and left again (at
// most 0.1 s), after_step(w) called after each step. Returns whether it touched.
template <class AfterStep>
bool flat_drop_on_a_fixed_box(World3d& w, const ContactParameters& contact, AfterStep after_step) {
    w.contact = contact;
    w.gravity_m_s2 = 0.0;
    w.dt_s = 1e-6;
    add_slab(w, BodyKind3d::fixed);
    RigidBody3d b = box("box", {0.5, 0.2, 0.2}, {0.0, 0.0, 0.1 + 1e-4}, 20.0);
    set_initial_velocity(b, {0.0, 0.0, -1.0}, {});
    add_body(w, b, BodyKind3d::dynamic);
    bool touched = false;
    while (w.time_s < 0.1 && !(touched && w.contacts.empty())) {
        step_3d(w);
        touched = touched || !w.contacts.empty();
        after_step(w);
    }
    return touched;
}

TEST(World3d, FlatDropOnAFixedBoxReboundsWithTheRequestedRestitution) {
    // tests/validation/test_table_contact_3d.cpp's setting, on a fixed box instead of the
    // half-space: no gravity, 1 m/s, kn = 1e6 N/m a point, dt = 1e-6 s. Tolerance 2%, the 2-D one.
    for (double e : {0.2, 0.6, 0.95}) {
        World3d w;
        const ContactParameters contact{.kn_N_m = 1e6, .ks_N_m = 1e6, .mu = 0.0, .h_n = damping_ratio_rebound(e), .h_s = 0.0};
        ASSERT_TRUE(flat_drop_on_a_fixed_box(w, contact, [](const World3d& now) {
            if (!now.contacts.empty()) EXPECT_EQ(now.contacts.size(), 4u);
        }));
        const double measured = w.bodies[1].velocity_m_s.z;
        EXPECT_NEAR(measured, e, 0.02 * e);
        std::printf("flat drop on a box: e requested %.2f, measured %.5f\n", e, measured);
    }
}

TEST(World3d, FlatDropWithZeroOverlapTerminationReboundsWithThePapersE) {
    // [contact] termination = "zero_overlap" (tests/validation/test_termination.cpp in 2-D): the
    // dashpot acts, pulling if it says so, until the overlap is zero, so the rebound is exactly the
    // paper's e = exp(-pi h / sqrt(1 - h^2)) of the linear spring-dashpot. Four points of 1e6 N/m
    // under a 20 kg box: a contact half period of pi / 447 s, about 7000 steps of 1e-6 s; the
    // dashpot's half-step lag costs O(h w dt) = 1e-3 of the rebound at most: 0.3 %, the 2-D
    // tolerance. The law's pulling branch is checked by the least force (below zero), and the
    // ledger across the impact to 2e-4 of the impact energy (its residual is O((w dt)^2)).
    for (double e : {0.3, 0.7}) {
        World3d w;
        const double h = damping_ratio_paper(e);
        ContactParameters contact{.kn_N_m = 1e6, .ks_N_m = 1e6, .mu = 0.5, .h_n = h, .h_s = 0.0};
        contact.termination = ContactTermination::zero_overlap;
        double least_force_n = 0.0;
        ASSERT_TRUE(flat_drop_on_a_fixed_box(w, contact, [&](const World3d& now) {
            for (const ContactPoint3d& c : now.contacts) least_force_n = std::min(least_force_n, c.force_n.z);
        }));
        const double rebound = w.bodies[1].velocity_m_s.z;
        EXPECT_NEAR(rebound, e, 0.003 * e);
        EXPECT_NEAR(rebound, restitution_of(h, ContactTermination::zero_overlap), 0.003 * e);
        EXPECT_LT(least_force_n, -1.0);  // the dashpot pulled as the overlap closed
        EXPECT_LT(w.ledger.balance_error(), 2e-4);
        std::printf("flat drop, zero_overlap: e %.2f, rebound %.5f (error %+.3f%%), least point force %.1f N, balance %.2e\n",
                    e, rebound, 100.0 * (rebound - e) / e, least_force_n, w.ledger.balance_error());
    }
}

TEST(World3d, SlidingOnADrivenBoxMatchesNewmark) {
    // The paper's Fig. 5 case on a driven slab (the table as a body): 1 kg, mu = 0.3,
    // a = 3.5 cos(2 pi t) m/s^2 at azimuth 0 and 30 degrees, four points of kn = ks = 1e4 N/m,
    // dt = 1e-4 s. Tolerance as on the half-space (and in 2-D): 2% of the slip plus the elastic
    // shear u_e = mu m g / (2 * 2e4).
    const ComponentMotion shaking = SineMotion{3.5, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    const auto reference = rigid_plastic_sliding(shaking, 0.3, g, 5.0, 1e-5);
    const double u_e = 0.3 * 1.0 * g / (2.0 * 2.0e4);
    for (double azimuth_deg : {0.0, 30.0}) {
        const double azimuth = azimuth_deg * std::numbers::pi / 180.0;
        World3d w;
        w.contact = {.kn_N_m = 1e4, .ks_N_m = 1e4, .mu = 0.3, .h_n = damping_ratio_paper(0.4), .h_s = 1.0};
        w.table.x = SineMotion{3.5 * std::cos(azimuth), 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
        w.table.y = SineMotion{3.5 * std::sin(azimuth), 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
        add_slab(w, BodyKind3d::driven);
        add_body(w, box("box", {0.5, 0.2, 0.2}, {0.0, 0.0, 0.1}, 1.0), BodyKind3d::dynamic);
        const Vec3 start = w.bodies[1].position_m;
        const Vec3 direction{std::cos(azimuth), std::sin(azimuth), 0.0};
        for (double cycles : {1.0, 5.0}) {
            while (w.time_s < cycles - 0.5 * w.dt_s) step_3d(w);
            const Vec3 slip = (w.bodies[1].position_m - start) - table_displacement(w.table, w.time_s);
            const double along = dot(slip, direction);
            const double ref = reference[static_cast<std::size_t>(std::llround(cycles / 1e-5))].relative_displacement_m;
            EXPECT_NEAR(along, ref, 0.02 * std::abs(ref) + u_e) << "azimuth " << azimuth_deg << ", " << cycles;
            std::printf("sliding on a driven box, azimuth %.0f deg, after %.0f cycle(s): slip %.4f mm, Newmark %.4f "
                        "mm (%.2f%%)\n",
                        azimuth_deg, cycles, 1e3 * along, 1e3 * ref, 100.0 * (along - ref) / ref);
        }
        // The half-space run closes to 1.9e-7; the same bound.
        EXPECT_LT(w.ledger.balance_error(), 1e-5);
        std::printf("sliding on a driven box, azimuth %.0f deg: energy balance error %.2e (friction %.4f J, table "
                    "work %.4f J)\n",
                    azimuth_deg, w.ledger.balance_error(), w.ledger.friction_j, w.ledger.table_work_j);
    }
}

TEST(World3d, EdgeOnEdgeCollisionKeepsTheMomenta) {
    // Two boxes turned 45 degrees about x and about y meet edge on edge, crossed at right angles
    // and off centre, with friction: one point, keyed by the two edges. The forces on the two are
    // equal and opposite at one point, so the total momentum and angular momentum (about the
    // origin, in the scheme's half-step form) are kept to round-off through the impact.
    World3d w;
    w.contact = {.kn_N_m = 1e6, .ks_N_m = 1e6, .mu = 0.5, .h_n = damping_ratio_rebound(0.5), .h_s = 0.5};
    w.gravity_m_s2 = 0.0;
    w.dt_s = 1e-5;
    const double quarter = std::numbers::pi / 4.0;
    const double half_diagonal = 0.1 * std::sqrt(2.0);
    RigidBody3d lower =
        box("lower", {0.6, 0.2, 0.2}, {0.05, 0.0, -half_diagonal}, 10.0, from_rotation_vector({quarter, 0, 0}));
    RigidBody3d upper =
        box("upper", {0.2, 0.5, 0.2}, {0.0, 0.07, half_diagonal + 1e-4}, 4.0, from_rotation_vector({0, quarter, 0}));
    set_initial_velocity(lower, {0.1, 0.0, 0.5}, {0.0, 0.0, 0.3});
    set_initial_velocity(upper, {-0.2, 0.1, -0.5}, {1.0, 0.0, 0.0});
    add_body(w, lower, BodyKind3d::dynamic);
    add_body(w, upper, BodyKind3d::dynamic);
    step_3d(w);
    const Momentum3d before = momentum(w);
    bool touched = false;
    std::size_t steps_in_contact = 0;
    while (w.time_s < 0.2 && !(touched && w.contacts.empty())) {
        step_3d(w);
        if (w.contacts.empty()) continue;
        touched = true;
        ++steps_in_contact;
        ASSERT_EQ(w.contacts.size(), 1u);
        EXPECT_EQ(feature_kind(w.contacts[0].key.feature_a), FeatureKind3d::edge);
        EXPECT_EQ(feature_kind(w.contacts[0].key.feature_b), FeatureKind3d::edge);
    }
    ASSERT_TRUE(touched);
    const Momentum3d after = momentum(w);
    const double p_scale = 10.0 * 0.5;
    const double l_scale = p_scale * 0.3;
    EXPECT_LT(length(after.linear_kg_m_s - before.linear_kg_m_s), 1e-13 * p_scale);
    EXPECT_LT(length(after.angular_kg_m2_s - before.angular_kg_m2_s), 1e-13 * l_scale);
    // And the impact did something: the upper box goes back up.
    EXPECT_GT(w.bodies[1].velocity_m_s.z, 0.0);
    std::printf("edge on edge: %zu steps in contact, momentum change %.2e kg m/s, angular momentum change %.2e "
                "kg m^2/s; upper box vz %.4f m/s after\n",
                steps_in_contact, length(after.linear_kg_m_s - before.linear_kg_m_s),
                length(after.angular_kg_m2_s - before.angular_kg_m2_s), w.bodies[1].velocity_m_s.z);
}

TEST(World3d, FreeRockingOnAFixedBoxFollowsTheHalfSpaceRun) {
    // tests/validation/test_rocking_3d.cpp's block (0.4 x 1.0 x 1.6 m, released at half its
    // slenderness angle about an edge), on a fixed 3 x 3 m slab instead of the half-space: through
    // the rocking and its impacts the slab's top face stays the reference and the points are the
    // block's corners below it, so the run follows the half-space one, which matches Housner (peaks
    // within 1.1%, tested there). They differ only in where a force acts (midway between the
    // surfaces, not at the corner: half an overlap, about 5e-6 m, under the friction force), so
    // the tolerance is 1e-3 of the release angle over 3 impacts (measured 3.8e-4).
    const double b = 0.2, h = 0.8, depth = 1.0;
    const double theta0 = 0.5 * std::atan(b / h);
    const Quaternion tilt = from_rotation_vector({0.0, -theta0, 0.0});
    const Vec3 center = Vec3{-b, 0.0, 0.0} + rotate(tilt, {b, 0.0, h});
    const RigidBody3d block = make_rigid_body_3d("block", box_vertices({2 * b, depth, 2 * h}, center, tilt), 1536.0);
    const ContactParameters contact{
        .kn_N_m = 0.5e9 * depth, .ks_N_m = 0.5e9 * depth, .mu = 2.0, .h_n = damping_ratio_paper(0.2), .h_s = 1.0};
    World3d w;
    w.contact = contact;
    w.dt_s = 2e-5;
    add_body(w, box("slab", {3.0, 3.0, 0.2}, {0.0, 0.0, -0.1}, 1800.0), BodyKind3d::fixed);
    add_body(w, block, BodyKind3d::dynamic);
    testing::TableRun3d half_space = testing::table_run(block, contact);
    half_space.dt_s = w.dt_s;
    const Quaternion start = block.orientation;
    double worst_rad = 0.0;
    int impacts = 0;
    double last_theta = theta0;
    while (w.time_s < 2.0 - 0.5 * w.dt_s) {
        step_3d(w);
        half_space.step();
        for (const ContactPoint3d& c : w.contacts) {
            ASSERT_EQ(feature_kind(c.key.feature_a), FeatureKind3d::face) << "at t = " << w.time_s;
            ASSERT_EQ(feature_kind(c.key.feature_b), FeatureKind3d::vertex) << "at t = " << w.time_s;
        }
        const double theta = -rotation_vector(w.bodies[1].orientation * conjugate(start)).y + theta0;
        const double theta_half_space = -rotation_vector(half_space.body.orientation * conjugate(start)).y + theta0;
        worst_rad = std::max(worst_rad, std::abs(theta - theta_half_space));
        if ((theta > 0.0) != (last_theta > 0.0)) ++impacts;
        last_theta = theta;
    }
    EXPECT_GE(impacts, 3);
    EXPECT_LT(worst_rad, 1e-3 * theta0);
    EXPECT_LT(w.ledger.balance_error(), 1e-3);
    std::printf("rocking on a fixed box: %d impacts in 2 s, largest difference from the half-space run %.2e rad "
                "(release %.4f rad), energy balance error %.2e (half-space %.2e)\n",
                impacts, worst_rad, theta0, w.ledger.balance_error(), half_space.ledger.balance_error());
}

TEST(World3d, StableTimeStepBoundsTheCubesRowsAndTheWallsInstability) {
    // A cube of side a and mass m flat on a fixed slab, kn only: the rows of its normal direction
    // are g = (z / sqrt(m), I^-1/2 (r x z)) with I = m a^2 / 6 and |r x z| components a/2, so the
    // largest row (a rotation) sums to 4 kn (sqrt(6)/2)(1 + sqrt(6)) / m, and dt = 2 / sqrt of it.
    World3d w;
    w.contact = {.kn_N_m = 1e6, .ks_N_m = 0.0, .mu = 0.6, .h_n = 0.0, .h_s = 0.0};
    add_slab(w, BodyKind3d::fixed);
    add_body(w, box("cube", {0.5, 0.5, 0.5}, {0.0, 0.0, 0.25 - 1e-5}, 100.0), BodyKind3d::dynamic);
    step_3d(w);
    ASSERT_EQ(w.contacts.size(), 4u);
    const double lambda = 4.0 * 1e6 * (std::sqrt(6.0) / 2.0) * (1.0 + std::sqrt(6.0)) / 100.0;
    EXPECT_NEAR(live_time_step_3d(w).dt_s, 2.0 / std::sqrt(lambda), 1e-12);
    // Each point's springs are kn times its stiffness share (geometry/corner_share_3d.hpp): with
    // every share halved the rows halve and the kn-only bound grows by sqrt 2; a share of 2 (the
    // sharpest corner) shortens it by sqrt 2.
    for (double share : {0.5, 2.0}) {
        World3d shared = w;
        for (ContactPoint3d& c : shared.contacts) c.stiffness_share = share;
        EXPECT_NEAR(live_time_step_3d(shared).dt_s, 2.0 / std::sqrt(share * lambda), 1e-12);
    }

    // The settled 288-box wall: measured unstable at 5e-5 s, stable at 2.5e-5 s (docs/3d.md). The
    // bound must lie below the unstable step, and a run at 0.9 of it closes its ledger.
    scenes::BrickWall3dDef def;
    def.courses = 6;
    def.bricks_per_course = 25;
    World3d wall = scenes::brick_wall_3d(def);
    for (int i = 0; i < 200; ++i) step_3d(wall);
    const CriticalTimeStep3d bound = live_time_step_3d(wall);
    EXPECT_LT(bound.dt_s, 5e-5);
    scenes::BrickWall3dDef at_bound = def;
    at_bound.dt_s = 0.9 * bound.dt_s;
    World3d stable = scenes::brick_wall_3d(at_bound);
    while (stable.time_s < 0.01) step_3d(stable);
    EXPECT_LT(stable.ledger.balance_error(), 2e-3);
    std::printf("3-D stable step: cube %.4e s; wall %.3e s (body %u, omega %.0f rad/s, h %.2f), at 0.9 of it the "
                "ledger closes to %.2e\n",
                live_time_step_3d(w).dt_s, bound.dt_s, bound.body, bound.omega_rad_s, bound.h,
                stable.ledger.balance_error());
}

// The state of every body as bytes, and the ledger's.
std::vector<unsigned char> state_bytes(const World3d& w) {
    std::vector<unsigned char> bytes;
    auto put = [&](const auto& v) {
        const auto* p = reinterpret_cast<const unsigned char*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof v);
    };
    for (const RigidBody3d& b : w.bodies) {
        put(b.position_m);
        put(b.orientation);
        put(b.velocity_m_s);
        put(b.angular_momentum_kg_m2_s);
    }
    for (const ContactPoint3d& c : w.contacts) put(c.shear.spring_n);
    put(w.ledger);
    return bytes;
}

TEST(World3d, BrickWallIsTheSameBytesAtOneAndTwoThreads) {
    // 288 boxes on a shaken base (more than 2048 points, so the loops do share out), 500 steps:
    // each parallel loop writes its own slots and totals go by fixed chunks (world/parallel.hpp).
#ifndef _OPENMP
    GTEST_SKIP() << "built without OpenMP";
#else
    scenes::BrickWall3dDef def;
    def.courses = 6;
    def.bricks_per_course = 25;
    def.shaking = SineMotion{3.0, 0.2, 0.0, 0.0, 0.0};
    std::vector<std::vector<unsigned char>> runs;
    std::size_t points = 0;
    const int threads_before = omp_get_max_threads();
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        World3d w = scenes::brick_wall_3d(def);
        for (int i = 0; i < 500; ++i) step_3d(w);
        points = w.contacts.size();
        runs.push_back(state_bytes(w));
        // And the wall is sound: it rides the base (3 m/s^2, below mu g), every box within 1 mm of
        // where it was placed relative to the base, the ledger closed (settling: measured 5e-4).
        const Vec3 base_shift = w.bodies[0].position_m - w.rest_positions_m[0];
        double worst_m = 0.0;
        for (std::size_t i = 1; i < w.bodies.size(); ++i)
            worst_m = std::max(worst_m, length(w.bodies[i].position_m - w.rest_positions_m[i] - base_shift));
        EXPECT_LT(worst_m, 1e-3);
        EXPECT_LT(w.ledger.balance_error(), 2e-3);
        std::printf("3-D wall, %d thread(s): %zu points, largest move against the base %.3e m, energy balance "
                    "error %.2e\n",
                    threads, points, worst_m, w.ledger.balance_error());
    }
    omp_set_num_threads(threads_before);
    EXPECT_GT(points, 2048u);
    EXPECT_EQ(runs[0], runs[1]);
#endif
}

TEST(World3d, PeersS3dWallIsTheSameBytesAtOneAndTwoThreads) {
    // The benchmark's scene (scenes/s3d_wall_3d.hpp, the peers' S3D) with 1100 bricks: settled,
    // then 150 shaken steps, at 1 and 2 threads.
#ifndef _OPENMP
    GTEST_SKIP() << "built without OpenMP";
#else
    scenes::S3dWallDef def;
    def.bricks = 1100;
    std::vector<std::vector<unsigned char>> runs;
    std::size_t points = 0;
    const int threads_before = omp_get_max_threads();
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        World3d w = scenes::settled_s3d_wall_3d(def);
        for (int i = 0; i < 150; ++i) step_3d(w);
        points = w.contacts.size();
        runs.push_back(state_bytes(w));
    }
    omp_set_num_threads(threads_before);
    // The layout: C = round(sqrt(1100)) = 33 bricks a wythe in even courses, 32 in odd ones.
    int per_course = 0;
    EXPECT_EQ(scenes::s3d_brick_centres(def, per_course).size(), 1100u);
    EXPECT_EQ(per_course, 33);
    EXPECT_GT(points, 2048u);  // more than a chunk: the loops do share out
    EXPECT_EQ(runs[0], runs[1]);
#endif
}

// The vertical force each bed joint of a settled S3D wall carries, over the weight of the
// courses above it (joint c lies under course c; joint 0 on the base). The pairs' forces are the
// step's own (ContactPairSums3d::force_n, on the pair's second body).
std::vector<double> bed_joint_load_ratios(const World3d& w, const scenes::S3dWallDef& def) {
    const auto course = [&](std::uint32_t i) {
        return static_cast<int>(std::lround((w.bodies[i].position_m.z - 0.5 * def.brick_m.z) / def.brick_m.z));
    };
    int courses = 0;
    for (std::uint32_t i = 1; i < w.bodies.size(); ++i) courses = std::max(courses, course(i) + 1);
    std::vector<double> carried_n(courses, 0.0);
    std::vector<double> weight_n(courses, 0.0);
    for (std::uint32_t i = 1; i < w.bodies.size(); ++i)
        for (int c = 0; c <= course(i); ++c) weight_n[c] += w.bodies[i].mass_kg * w.gravity_m_s2;
    for (const ContactPairSums3d& p : w.scratch.contact_pairs) {
        const auto [a, b] = w.scratch.pairs[p.candidate];
        if (a == 0) {
            carried_n[0] += p.force_n.z;  // the base (body 0) under a brick of course 0
        } else if (course(b) > course(a)) {
            carried_n[course(b)] += p.force_n.z;
        } else if (course(a) > course(b)) {
            carried_n[course(a)] -= p.force_n.z;
        }
    }
    std::vector<double> ratios(courses);
    for (int c = 0; c < courses; ++c) ratios[c] = carried_n[c] / weight_n[c];
    return ratios;
}

TEST(World3d, PeersS3dWallCarriesItsWeightAtEveryBedJointOnceSettled) {
    // S3D times a wall whose every bed joint carries its load (shared/peers/three_d/README.md). With
    // kn lowered to 1e6 N/m a point, the compression climbs one course in about 7 steps: placed
    // touching, a 24-course wall (2100 bricks) was still falling after its 100 settling steps, its
    // base carrying 54 % of its weight and its upper 8 joints nothing. The scene now places each
    // course at the springs' static compression (scenes/s3d_wall_3d.cpp, course_sinking_m).
    // Tolerance 5 %: the settling's remaining ringing (h_n = 0.05) and the running bond's unequal
    // supports at the wall's ends (measured worst 2.1 %, at the top joint).
    scenes::S3dWallDef def;
    def.bricks = 2100;
    const World3d w = scenes::settled_s3d_wall_3d(def);
    const std::vector<double> ratios = bed_joint_load_ratios(w, def);
    ASSERT_EQ(ratios.size(), 24u);
    for (std::size_t c = 0; c < ratios.size(); ++c) EXPECT_NEAR(ratios[c], 1.0, 0.05) << "bed joint under course " << c;
}

TEST(World3d, PeersS3dWallAbove2048BodiesIsTheSameBytesAtOneAndTwoThreads) {
    // 2100 bricks: more than parallel_threshold bodies, candidate pairs and listed pairs, so that
    // every loop of the step takes its shared-out path: the pose, the skin's containment test and
    // its chunked filter (broad_phase/skin_pair_list.hpp), the table's chunked layout, and each
    // body gathering its pairs' sums (world/step_3d.cpp). 20 settling steps, then 40 shaken ones
    // (the bytes need no settled wall, and the test stays a few seconds).
#ifndef _OPENMP
    GTEST_SKIP() << "built without OpenMP";
#else
    scenes::S3dWallDef def;
    def.bricks = 2100;
    def.settling_steps = 20;
    std::vector<std::vector<unsigned char>> runs;
    std::size_t candidates = 0;
    std::size_t listed = 0;
    const int threads_before = omp_get_max_threads();
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        World3d w = scenes::settled_s3d_wall_3d(def);
        for (int i = 0; i < 40; ++i) step_3d(w);
        candidates = w.scratch.pairs.size();
        listed = w.scratch.broad_phase.listed_pairs();
        runs.push_back(state_bytes(w));
    }
    omp_set_num_threads(threads_before);
    EXPECT_GT(candidates, 2048u);
    EXPECT_GT(listed, 2048u);
    EXPECT_EQ(runs[0], runs[1]);
#endif
}

}  // namespace
}  // namespace blockdem
