// The two rules for when a contact ends ([contact] termination), each against the analytical
// restitution of the linear spring-dashpot, and the energy ledger across the impact.
//
// zero_overlap (Ohmachi and Arai's rule): the contact acts, pulling if the dashpot says so,
// until the overlap is zero; the overlap then follows x = (V / p_c) exp(-h p t) sin(p_c t) over
// a whole half period and the rebound is exactly e = exp(-pi h / sqrt(1 - h^2)), the inverse of
// the paper's h_n formula. no_tension: the force is clamped at zero, the contact stops pushing
// when K x + C x' = 0, before the overlap closes, and the rebound is Schwager and Poeschel's
// closed form (laws/restitution.cpp), above e.
//
// No gravity, so the rebound is the contact's alone. dt = 1e-6 s against a contact period of
// pi / 1000 s: about 3000 steps per impact; the central difference's lag of half a step in the
// dashpot's velocity costs O(h w dt) = 1e-3 of the rebound at most, so 0.3% is the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "laws/linear_spring_dashpot.hpp"
#include "support/world_helpers.hpp"

namespace blockdem {
namespace {

using testing::contact;
using testing::model_with;
using testing::rectangle_body;

constexpr double kn = 1.0e6;   // [N/m]
constexpr double dt = 1.0e-6;  // [s]

struct Impact {
    double rebound = 0.0;         ///< [-] rebound speed / approach speed
    double energy_residual = 0.0; ///< [-] ledger residual after the impact / impact energy
    double dissipated = 0.0;      ///< [-] normal dashpot's dissipation / impact energy
    double least_force_n = 0.0;   ///< [N] least normal force seen during the impact
};

// A 1 kg block falls flat at 1 m/s onto a fixed table (two corner points, M = 1/2 kg each).
Impact flat_drop(double h_n, ContactTermination termination, double step_s = dt) {
    ContactParameters c = contact(kn, 0.0, h_n, 0.0);
    c.termination = termination;
    Model m = model_with({rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0, -0.1}),
                          rectangle_body("block", BodyKind::dynamic, 0.5, 0.2, {0, 0.1001})},
                         c, step_s, 0.0);
    m.bodies[1].velocity_m_s = {0.0, -1.0};
    World w = build_world(m);
    const std::uint32_t block = w.body_id("block");
    Impact out;
    bool touched = false;
    testing::step_until(w, 0.1, [&](const World& world) {
        const int n = testing::contact_points_of(world, block);
        for (const PairContact& pair : world.contacts)
            for (std::uint32_t k = 0; k < pair.count; ++k) out.least_force_n = std::min(out.least_force_n, pair.points[k].normal_force_n);
        if (n > 0) touched = true;
        return touched && n == 0;
    });
    EXPECT_TRUE(touched);
    const double impact_energy_j = 0.5 * 1.0 * 1.0;
    out.rebound = w.bodies.velocity_m_s[block].y;
    out.energy_residual = w.energy.residual_j() / impact_energy_j;
    out.dissipated = w.energy.normal_dashpot_j / impact_energy_j;
    return out;
}

TEST(Termination, ZeroOverlapReboundsWithThePapersE) {
    for (double e : {0.2, 0.4, 0.6, 0.8, 0.95}) {
        const double h = damping_ratio_paper(e);
        const Impact i = flat_drop(h, ContactTermination::zero_overlap);
        EXPECT_NEAR(i.rebound, e, 0.003 * e) << "paper e = " << e;
        EXPECT_NEAR(i.rebound, restitution_of(h, ContactTermination::zero_overlap), 0.003 * e);
        // The dashpot pulled at the end of the contact: the force went negative.
        EXPECT_LT(i.least_force_n, -0.01 * kn * 1.0 / 1000.0) << "e = " << e;
        std::printf("zero_overlap: paper e = %.3f (h_n = %.4f): rebound %.5f (error %+.3f%%), least force %.1f N\n", e, h,
                    i.rebound, 100.0 * (i.rebound - e) / e, i.least_force_n);
    }
}

TEST(Termination, NoTensionReboundsWithSchwagerPoeschel) {
    for (double e : {0.2, 0.4, 0.6, 0.8, 0.95}) {
        const double h = damping_ratio_paper(e);
        const Impact i = flat_drop(h, ContactTermination::no_tension);
        const double expected = restitution_of(h, ContactTermination::no_tension);
        EXPECT_NEAR(i.rebound, expected, 0.003 * expected) << "paper e = " << e;
        EXPECT_GT(i.rebound - e, 0.5 * (expected - e));  // above the paper's e, by the closed form's margin
        EXPECT_GE(i.least_force_n, 0.0);
        std::printf("no_tension:   paper e = %.3f (h_n = %.4f): rebound %.5f, closed form %.5f (error %+.3f%%)\n", e, h,
                    i.rebound, expected, 100.0 * (i.rebound - expected) / expected);
    }
}

TEST(Termination, LedgerClosesAcrossTheImpact) {
    // Everything the block had is kinetic energy again or in the dashpot's column: the ledger's
    // residual after the impact is O((w dt)^2) of the impact energy, with either rule, and the
    // dissipation is 1 - e^2 of it. At a coarse dt (w dt = 0.028, 110 steps an impact), so that
    // the dashpot's work over the step in which a pulling point opens, C v^2 dt / 2 (about
    // 2e-3 of the impact energy here), would show if the ledger missed it.
    for (ContactTermination rule : {ContactTermination::zero_overlap, ContactTermination::no_tension}) {
        for (double e : {0.3, 0.7}) {
            const double h = damping_ratio_paper(e);
            const Impact i = flat_drop(h, rule, 2.0e-5);
            EXPECT_LT(std::abs(i.energy_residual), 2e-4) << to_string(rule) << " e = " << e;
            EXPECT_NEAR(i.dissipated, 1.0 - i.rebound * i.rebound, 2e-4) << to_string(rule) << " e = " << e;
            std::printf("%s, h_n = %.4f: dissipated %.6f of the impact energy, 1 - rebound^2 = %.6f, residual %.2e\n",
                        to_string(rule), h, i.dissipated, 1.0 - i.rebound * i.rebound, i.energy_residual);
        }
    }
}

TEST(Termination, HeadOnEqualBlocksZeroOverlap) {
    // Two free bodies: the reduced mass sizes the dashpot, and the rebound is e again.
    for (double e : {0.3, 0.7}) {
        ContactParameters c = contact(kn, 0.0, damping_ratio_paper(e), 0.0);
        c.termination = ContactTermination::zero_overlap;
        Model m = model_with({rectangle_body("left", BodyKind::dynamic, 0.2, 0.2, {-0.1005, 0}),
                              rectangle_body("right", BodyKind::dynamic, 0.2, 0.2, {0.1005, 0})},
                             c, dt, 0.0);
        m.bodies[0].velocity_m_s = {1.0, 0.0};
        m.bodies[1].velocity_m_s = {-1.0, 0.0};
        World w = build_world(m);
        bool touched = false;
        testing::step_until(w, 0.2, [&](const World& world) {
            const int n = testing::contact_points_of(world, 0);
            if (n > 0) touched = true;
            return touched && n == 0;
        });
        ASSERT_TRUE(touched);
        const double separation_speed = w.bodies.velocity_m_s[1].x - w.bodies.velocity_m_s[0].x;
        EXPECT_NEAR(separation_speed / 2.0, e, 0.003 * e);
        std::printf("head-on, zero_overlap: paper e = %.3f, measured %.5f\n", e, separation_speed / 2.0);
    }
}

TEST(Termination, PullingPointHoldsNoShear) {
    // The law alone: a point separating fast enough for the dashpot to pull carries no shear force,
    // and its shear spring relaxes to zero (the excess to friction).
    ContactParameters p = contact(1.0e6, 0.5, 0.5, 0.0);
    p.termination = ContactTermination::zero_overlap;
    const DashpotCoefficients c = dashpot_coefficients(p, 1.0);
    const ContactKinematics k{1e-4, 2.0, 0.01};   // 0.1 mm overlap, separating at 2 m/s
    const ContactHistory before{30.0, 0.0, 0.0};  // a shear spring loaded to 30 N
    const ContactForce f = linear_spring_dashpot(p, c, k, before, 1e-6);
    EXPECT_NEAR(f.normal_n, 1.0e6 * 1e-4 - c.cn_N_s_m * 2.0, 1e-9);
    EXPECT_LT(f.normal_n, 0.0);
    EXPECT_EQ(f.shear_n, 0.0);
    EXPECT_EQ(f.shear_spring_n, 0.0);
    EXPECT_TRUE(f.sliding);
    EXPECT_GT(f.friction_work_j, 0.0);
    p.termination = ContactTermination::no_tension;
    EXPECT_EQ(linear_spring_dashpot(p, c, k, before, 1e-6).normal_n, 0.0);
}

}  // namespace
}  // namespace blockdem
