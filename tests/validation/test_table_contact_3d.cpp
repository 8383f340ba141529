// A box on the table in 3-D (contact/table_contact_3d.hpp) reduced to the 2-D suite's closed
// forms: a flat drop rebounds with the requested restitution, and a box on a sinusoidally shaken
// table slides as Newmark's rigid-plastic block (analysis/rigid_plastic_sliding.hpp), along the
// shaking whatever its azimuth (isotropic friction). The energy ledger (world/energy_ledger.hpp)
// is filled as in 2-D and must close.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "analysis/rigid_plastic_sliding.hpp"
#include "contact/table_contact_3d.hpp"
#include "dynamics/rigid_rotation_3d.hpp"
#include "laws/restitution.hpp"
#include "motion/table_motion.hpp"
#include "support/table_run_3d.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;

using BoxOnTable = testing::TableRun3d;

// A 0.5 x 0.2 x 0.2 m box of mass_kg, its base at height base_z_m, turned by yaw_rad about the vertical.
BoxOnTable box_on_table(double mass_kg, double base_z_m, double yaw_rad, const ContactParameters& contact) {
    const Vec3 lengths{0.5, 0.2, 0.2};
    BoxOnTable s{.body = make_rigid_body_3d(
                     "box", box_vertices(lengths, {0.0, 0.0, base_z_m + 0.1}, from_rotation_vector({0, 0, yaw_rad})),
                     mass_kg / (0.5 * 0.2 * 0.2)),
                 .vertices = {},
                 .contact = contact};
    s.vertices.resize(s.body.shape.vertices_m.size());
    return s;
}

TEST(TableContact3d, FlatDropReboundsWithTheRequestedRestitution) {
    // The 2-D test's setting (tests/validation/test_restitution_impact.cpp): no gravity, 1 m/s
    // onto the table, kn = 1e6 N/m a point, dt = 1e-6 s (about 2000 steps per impact); the box's
    // four base corners share its mass in their dashpots, so it rebounds with e. Tolerance 2%, the
    // 2-D one. Turned about the vertical or not: the same.
    for (double yaw : {0.0, 0.6}) {
        for (double e : {0.2, 0.6, 0.95}) {
            const ContactParameters contact{
                .kn_N_m = 1e6, .ks_N_m = 1e6, .mu = 0.0, .h_n = damping_ratio_rebound(e), .h_s = 0.0};
            BoxOnTable s = box_on_table(20.0, 1e-4, yaw, contact);
            s.gravity_m_s2 = 0.0;
            s.dt_s = 1e-6;
            set_initial_velocity(s.body, {0.0, 0.0, -1.0}, {});
            bool touched = false;
            while (s.time_s < 0.1 && !(touched && s.last.points == 0)) {
                s.step();
                touched = touched || s.last.points > 0;
                if (s.last.points > 0) EXPECT_EQ(s.last.points, 4);
            }
            ASSERT_TRUE(touched);
            const double measured = s.body.velocity_m_s.z;
            EXPECT_NEAR(measured, e, 0.02 * e) << "yaw " << yaw << ", requested e = " << e;
            // A flat drop stays flat: no rotation from four symmetric points. The ledger closes
            // (measured 1e-7 of the impact's energy at e = 0.95, 4e-9 below).
            EXPECT_LT(length(s.body.angular_velocity_at_t_rad_s), 1e-9);
            EXPECT_LT(s.ledger.balance_error(), 1e-6) << "yaw " << yaw << ", e = " << e;
            std::printf(
                "3-D flat drop, yaw %.1f rad: requested e = %.3f, measured %.4f (error %.2f%%), energy balance %.1e\n",
                yaw, e, measured, 100.0 * (measured - e) / e, s.ledger.balance_error());
        }
    }
}

TEST(TableContact3d, OneCornerImpactFollowsTheEffectiveMass) {
    // The 2-D one-corner test in 3-D: a box turned about a skew axis lands on one corner (no
    // gravity, no friction). The dashpot is sized with the box's mass m, but the corner moves with
    // m_eff = 1 / (1/m + (r x n) . I^-1 (r x n)), I the world inertia tensor: its damping ratio is
    // h sqrt(m / m_eff) and the corner rebounds with that ratio's restitution. Tolerance 3%, the
    // 2-D one. The box turns during the impact, so the lever r changes: by an amount first order
    // in the impact's duration (measured 2.8% off at kn = 1e6 N/m, 0.27% at 1e8), hence the stiff
    // contact and its step here.
    const double e = 0.6;
    const ContactParameters contact{
        .kn_N_m = 1e8, .ks_N_m = 1e8, .mu = 0.0, .h_n = damping_ratio_rebound(e), .h_s = 0.0};
    const Quaternion turn = from_rotation_vector({0.35, -0.25, 0.4});
    RigidBody3d probe = make_rigid_body_3d("box", box_vertices({0.5, 0.2, 0.2}, {}, turn), 500.0);
    std::size_t lowest = 0;
    for (std::size_t i = 1; i < probe.shape.vertices_m.size(); ++i)
        if (world_vertex(probe, i).z < world_vertex(probe, lowest).z) lowest = i;
    BoxOnTable s{
        .body = make_rigid_body_3d(
            "box", box_vertices({0.5, 0.2, 0.2}, {0.0, 0.0, -world_vertex(probe, lowest).z + 1e-4}, turn), 500.0),
        .vertices = std::vector<VertexContact3d>(8),
        .contact = contact};
    s.gravity_m_s2 = 0.0;
    s.dt_s = 1e-7;
    set_initial_velocity(s.body, {0.0, 0.0, -1.0}, {});
    const Vec3 n{0.0, 0.0, 1.0};
    const Vec3 arm = world_vertex(s.body, lowest) - s.body.position_m;
    // (r x n) . I^-1 (r x n) with I^-1 = R diag(1/I) R^T: in the body frame.
    const Vec3 lever_body = rotate_inverse(s.body.orientation, cross(arm, n));
    const double m_eff =
        1.0 / (1.0 / s.body.mass_kg + dot(lever_body, hadamard(s.body.inverse_moments_1_kg_m2, lever_body)));
    bool touched = false;
    while (s.time_s < 0.1 && !(touched && s.last.points == 0)) {
        s.step();
        touched = touched || s.last.points > 0;
        EXPECT_LE(s.last.points, 1);
    }
    ASSERT_TRUE(touched);
    const Vec3 omega = rotate(s.body.orientation, s.body.angular_velocity_body_rad_s);
    const Vec3 corner_velocity = s.body.velocity_m_s + cross(omega, world_vertex(s.body, lowest) - s.body.position_m);
    const double expected = restitution_no_tension(contact.h_n * std::sqrt(s.body.mass_kg / m_eff));
    EXPECT_NEAR(corner_velocity.z, expected, 0.03 * expected) << "m / m_eff = " << s.body.mass_kg / m_eff;
    EXPECT_LT(corner_velocity.z, e);
    EXPECT_LT(s.ledger.balance_error(), 1e-6);
    std::printf(
        "3-D one-corner impact: requested e = %.3f, m/m_eff = %.3f, corner rebound %.4f, predicted %.4f (%.2f%%)\n", e,
        s.body.mass_kg / m_eff, corner_velocity.z, expected, 100.0 * (corner_velocity.z - expected) / expected);
}

TEST(TableContact3d, SlidingMatchesNewmarkRigidPlasticInAnyAzimuth) {
    // The paper's Fig. 5 case (tests/validation/test_sliding.cpp): 1 kg, mu = 0.3, a = 3.5 cos(2 pi t)
    // m/s^2, dt = 1e-4 s, h_s = 1. The 2-D block stands on two corners of kn = ks = 2e4 N/m; the
    // box stands on four of 1e4 N/m, the same total stiffness. Tolerance, the 2-D one and for the
    // same reasons: 2% of the slip plus the elastic shear u_e = mu m g / (2 * 2e4) = 74 um. The
    // shaking's azimuth is 0 (along the box) and 30 degrees (across its edges): friction is
    // isotropic, so the slip follows the shaking and its size does not change.
    const ContactParameters contact{
        .kn_N_m = 1e4, .ks_N_m = 1e4, .mu = 0.3, .h_n = damping_ratio_paper(0.4), .h_s = 1.0};
    const ComponentMotion shaking = SineMotion{3.5, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    const auto reference = rigid_plastic_sliding(shaking, 0.3, g, 5.0, 1e-5);
    const double u_e = 0.3 * 1.0 * g / (2.0 * 2.0e4);
    for (double azimuth_deg : {0.0, 30.0}) {
        const double azimuth = azimuth_deg * std::numbers::pi / 180.0;
        BoxOnTable s = box_on_table(1.0, 0.0, 0.0, contact);
        s.horizontal = shaking;
        s.direction = {std::cos(azimuth), std::sin(azimuth), 0.0};
        const Vec3 start = s.body.position_m;
        double worst_across_m = 0.0;
        for (double cycles : {1.0, 5.0}) {
            while (s.time_s < cycles - 0.5 * s.dt_s) s.step();
            const Vec3 slip = (s.body.position_m - start) - s.table_displacement(s.time_s);
            const double along = dot(slip, s.direction);
            const double across = length(slip - along * s.direction - Vec3{0, 0, slip.z});
            worst_across_m = std::max(worst_across_m, across);
            const double ref = reference[static_cast<std::size_t>(std::llround(cycles / 1e-5))].relative_displacement_m;
            EXPECT_NEAR(along, ref, 0.02 * std::abs(ref) + u_e)
                << "azimuth " << azimuth_deg << ", after " << cycles << " cycles";
            std::printf(
                "3-D sliding, azimuth %.0f deg, after %.0f cycle(s): slip %.4f mm, Newmark %.4f mm (%.2f%%), across "
                "%.2g mm\n",
                azimuth_deg, cycles, 1e3 * along, 1e3 * ref, 100.0 * (along - ref) / ref, 1e3 * across);
        }
        // Across the shaking: nothing when it runs along the box's axis (symmetry). At 30
        // degrees the box rocks on its springs about an axis that is not a principal one, so it
        // also turns about the other (I^-1 T is not along T); its corners' loads and slips then
        // differ and it walks sideways a little (measured 0.048 mm, 0.8% of the slip, with
        // 3e-5 rad of yaw): bounded by the along tolerance.
        EXPECT_LT(worst_across_m,
                  azimuth_deg == 0.0 ? 1e-9 : 0.02 * std::abs(reference.back().relative_displacement_m) + u_e);
        // The ledger closes as in 2-D: measured 1.9e-7 of the largest term.
        EXPECT_LT(s.ledger.balance_error(), 1e-5);
        std::printf(
            "3-D sliding, azimuth %.0f deg: yaw %.2g rad, energy balance error %.2e (friction %.4f J, table work %.4f "
            "J)\n",
            azimuth_deg,
            rotation_vector(s.body.orientation * conjugate(box_on_table(1.0, 0.0, 0.0, contact).body.orientation)).z,
            s.ledger.balance_error(), s.ledger.friction_j, s.ledger.table_work_j);
    }
}

TEST(TableContact3d, VerticalTableMotionChangesTheFrictionCapacity) {
    // The 2-D test (tests/validation/test_sliding.cpp) with the table's third component: the table
    // also accelerates downwards at 0.3 g (after a smooth 0.3 s start), the normal force drops to
    // m (g - 0.3 g), and shaking at 0.8 mu g, which could not move the box before, makes it slide
    // with |a| = mu (g - 0.3 g) on the plateaus of sliding. Tolerance 1%, the 2-D one.
    const ContactParameters contact{
        .kn_N_m = 1e4, .ks_N_m = 1e4, .mu = 0.3, .h_n = damping_ratio_paper(0.4), .h_s = 1.0};
    BoxOnTable s = box_on_table(1.0, 0.0, 0.0, contact);
    s.horizontal = SineMotion{0.8 * 0.3 * g, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    s.vertical = make_acceleration_series({0.0, 0.3, 2.0}, {0.0, -0.3 * g, -0.3 * g});
    const double capacity = 0.3 * 0.7 * g;
    std::size_t count = 0, run_length = 0;
    double worst = 0.0;
    while (s.time_s < 2.0) {
        s.step();
        run_length = s.last.sliding_points == 4 ? run_length + 1 : 0;
        if (s.time_s < 0.5 || run_length < 200) continue;  // 20 ms into a plateau, after the start
        ++count;
        worst = std::max(worst, std::abs(std::abs(s.body.force_n.x / s.body.mass_kg) - capacity) / capacity);
    }
    EXPECT_GT(count, 1000u);
    EXPECT_LT(worst, 0.01);
    EXPECT_LT(s.ledger.balance_error(), 1e-4);
    std::printf(
        "3-D, vertical -0.3 g: sliding plateau %zu samples, largest deviation from mu (g + a_v) %.4f, ledger %.1e\n",
        count, worst, s.ledger.balance_error());
}

// The rigid-plastic block on a table shaken in two horizontal directions, integrated on its own:
// the relative velocity u' of block over table obeys u'' = -a_table - mu g u'/|u'| while it slides;
// it sticks (u' = 0) while |a_table| <= mu g. Each step takes the table's kick first; if friction
// could stop the relative motion within the step (|u' - a dt| <= mu g dt) it does, otherwise it
// acts against the kicked velocity: first order in dt, exact for the stick. Returns the slip at
// the sample times.
std::vector<Vec3> bidirectional_rigid_plastic(const ComponentMotion& x, const ComponentMotion& y, double mu,
                                              const std::vector<double>& at_s, double dt_s) {
    std::vector<Vec3> slips;
    Vec3 slip, velocity;
    double t = 0.0;
    for (double until : at_s) {
        while (t < until - 0.5 * dt_s) {
            const Vec3 table_a{sample(x, t + 0.5 * dt_s).acceleration_m_s2, sample(y, t + 0.5 * dt_s).acceleration_m_s2,
                               0.0};
            const Vec3 kicked = velocity - dt_s * table_a;
            const double stop_m_s = mu * g * dt_s;
            const Vec3 next = length(kicked) <= stop_m_s ? Vec3{} : kicked - (stop_m_s / length(kicked)) * kicked;
            slip += 0.5 * dt_s * (velocity + next);
            velocity = next;
            t += dt_s;
        }
        slips.push_back(slip);
    }
    return slips;
}

TEST(TableContact3d, BidirectionalSlidingMatchesTheVectorRigidPlasticBlock) {
    // The table shaken at once along x (3.5 cos 2 pi t) and along y (3.0 sin(2 pi t / 0.7)), both
    // above mu g = 2.94 m/s^2 at their peaks: the slip turns in the plane, and its vector follows
    // the rigid-plastic block's with friction opposite the relative velocity. Tolerance per
    // component, the 1-D one: 2% of the slip's length plus the elastic shear u_e = 74 um.
    // What the difference is: the DEM's friction force is its shear springs' force, which turns
    // with the slip only after the springs have followed it, so it lags the rigid-plastic
    // direction by an angle of order u_e over the slip's radius of turn. Measured at 3 s:
    // 1.03 mm of 51 mm at the paper's stiffness, 0.107 mm at 10 times, 0.013 mm at 100 times
    // (dt by sqrt(k)): first order in 1/k, so the test also asserts that 10 times stiffer
    // springs come 5 times closer.
    const ComponentMotion x = SineMotion{3.5, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    const ComponentMotion y = SineMotion{3.0, 0.7, 0.0, 0.0, 0.0};
    const std::vector<double> at_s = {1.0, 2.0, 3.0};
    const std::vector<Vec3> reference = bidirectional_rigid_plastic(x, y, 0.3, at_s, 1e-5);
    const double u_e = 0.3 * 1.0 * g / (2.0 * 2.0e4);
    std::vector<double> difference_at_end_m;
    for (double stiffer : {1.0, 10.0}) {
        const ContactParameters contact{
            .kn_N_m = 1e4 * stiffer, .ks_N_m = 1e4 * stiffer, .mu = 0.3, .h_n = damping_ratio_paper(0.4), .h_s = 1.0};
        BoxOnTable s = box_on_table(1.0, 0.0, 0.0, contact);
        s.dt_s = 1e-4 / std::sqrt(stiffer);
        s.horizontal = x;
        s.along_y = y;
        const Vec3 start = s.body.position_m;
        for (std::size_t k = 0; k < at_s.size(); ++k) {
            while (s.time_s < at_s[k] - 0.5 * s.dt_s) s.step();
            Vec3 slip = (s.body.position_m - start) - s.table_displacement(s.time_s);
            slip.z = 0.0;
            const double tolerance = 0.02 * length(reference[k]) + u_e;
            EXPECT_NEAR(slip.x, reference[k].x, tolerance) << "at " << at_s[k] << " s";
            EXPECT_NEAR(slip.y, reference[k].y, tolerance) << "at " << at_s[k] << " s";
            std::printf(
                "3-D bidirectional sliding, kn = ks = %.0e N/m, at %.0f s: slip (%.3f, %.3f) mm, rigid-plastic "
                "(%.3f, %.3f) mm, |difference| %.3f mm\n",
                contact.ks_N_m, at_s[k], 1e3 * slip.x, 1e3 * slip.y, 1e3 * reference[k].x, 1e3 * reference[k].y,
                1e3 * length(slip - reference[k]));
            if (k + 1 == at_s.size()) difference_at_end_m.push_back(length(slip - reference[k]));
        }
        // The ledger closes (measured 3.1e-5 and 1.0e-5 of the largest term).
        EXPECT_LT(s.ledger.balance_error(), 1e-4);
    }
    EXPECT_LT(difference_at_end_m[1], 0.2 * difference_at_end_m[0]);
}

TEST(TableContact3d, VectorRigidPlasticReferenceReducesToNewmark) {
    // The reference above, shaken along x only, against the 1-D Newmark integration: checks the
    // independent integration itself (first order in dt: 1e-5 s gives well under 0.1%).
    const ComponentMotion shaking = SineMotion{3.5, 1.0, std::numbers::pi / 2.0, 0.0, 0.0};
    const Vec3 slip = bidirectional_rigid_plastic(shaking, RestMotion{}, 0.3, {2.0}, 1e-5)[0];
    const double newmark = rigid_plastic_sliding(shaking, 0.3, g, 2.0, 1e-5)[200000].relative_displacement_m;
    EXPECT_NEAR(slip.x, newmark, 1e-3 * std::abs(newmark));
    EXPECT_EQ(slip.y, 0.0);
}

}  // namespace
}  // namespace blockdem
