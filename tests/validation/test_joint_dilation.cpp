// Joint dilation (laws/mohr_coulomb_joint.hpp, UDEC's psi) against its closed form: direct
// shear under a constant normal load. A 2 m x 5 cm block of 1000 kg slides down a fixed table
// tilted 40 deg (gravity turned; mu = 0.6 < tan 40 deg), with psi = 20 deg: the normal load is
// the block's weight, free to lift it, so the block rises by tan(psi) times its slip.
// Tolerance, and why: the rise differs from tan(psi) x slip only by the change of the joint's
// elastic closure (N / (JKN A) = 4e-6 m, against a rise of several centimetres) and the shear
// spring's elastic part of the travel (tau / JKS, 6e-6 m): 1e-3 of the rise covers both with
// margin (measured: -0.009 %). The energy balance: the same run without dilation is the
// reference; the dilating run's ledger must close as well as it does (both are printed; the
// lagging law of an earlier attempt let the error reach twice the largest term here).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::deg;

struct Slide {
    double slip_m = 0.0;
    double rise_m = 0.0;
    double balance_error = 0.0;
    double largest_balance_error = 0.0;  ///< over every step from 0.1 s
    World world;
};

Slide slide(double psi_rad) {
    const double width = 2.0, height = 0.05, mass = 1000.0;
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = 1e9;
    p.ks_pa_m = 5e8;
    p.mu = 0.6;
    p.h_n = 0.5;
    p.h_s = 0.5;
    p.tan_dilation = std::tan(psi_rad);
    Model m = testing::model_with({testing::rectangle_body("table", BodyKind::fixed, 3.0, 0.2, {0.0, -0.1}),
                                   testing::rectangle_body("block", BodyKind::dynamic, width, height, {0.0, 0.5 * height}, 0.0,
                                                           mass)},
                                  p, 0.0, 9.81, 0.5);
    m.settings.dt_s.reset();
    m.settings.dt_safety = 0.3;
    m.settings.tilt_rad = 40.0 * deg;
    Slide s{.world = build_world(m)};
    World& w = s.world;
    while (w.time_s < 0.5) {
        step_begin(w);
        step_end(w);
        // (From 0.1 s: at the start every term is small, and both runs' error is the settling's.)
        if (w.time_s > 0.1) s.largest_balance_error = std::max(s.largest_balance_error, w.energy.balance_error());
    }
    // The middle of the block's base: the centroid's travel plus the turn times h / 2.
    s.slip_m = std::abs((w.bodies.position_m[1].x - w.bodies.initial_position_m[1].x) + w.bodies.rotation_rad[1] * 0.5 * height);
    s.rise_m = w.bodies.position_m[1].y - w.bodies.initial_position_m[1].y;
    s.balance_error = w.energy.balance_error();
    return s;
}

TEST(JointDilation, DirectShearUnderConstantNormalLoadRisesByTanPsiTimesSlip) {
    const double psi = 20.0 * deg;
    const Slide dry = slide(0.0);
    const Slide dilating = slide(psi);
    std::printf("direct shear, psi = 20 deg: slip %.5f m, rise %.6f m against tan(psi) x slip %.6f m (%+.4f %%); energy "
                "balance error at the end %.2e (largest %.2e), without dilation %.2e (%.2e); slip against the dry run's %.4f\n",
                dilating.slip_m, dilating.rise_m, std::tan(psi) * dilating.slip_m,
                100.0 * (dilating.rise_m / (std::tan(psi) * dilating.slip_m) - 1.0), dilating.balance_error,
                dilating.largest_balance_error, dry.balance_error, dry.largest_balance_error, dilating.slip_m / dry.slip_m);
    ASSERT_GT(dilating.slip_m, 0.1);  // it slid
    // The normal force carries the rise's acceleration tan(psi) a, so the friction is
    // mu (N + m tan(psi) a) and the block slides at g (sin a - mu cos a) / (1 + mu tan(psi)):
    // against the dry run's slip, 1 / (1 + mu tan(psi)) = 0.8207 (measured 0.8208; 0.2 %: both
    // runs start as built and close their joint in the first milliseconds).
    EXPECT_NEAR(dilating.slip_m / dry.slip_m, 1.0 / (1.0 + 0.6 * std::tan(psi)), 0.002);
    EXPECT_NEAR(dilating.rise_m, std::tan(psi) * dilating.slip_m, 1e-3 * std::tan(psi) * dilating.slip_m);
    EXPECT_NEAR(dry.rise_m, 0.0, 1e-5);
    const World& w = dilating.world;
    ASSERT_EQ(w.contacts.size(), 1u);
    ASSERT_EQ(w.contacts[0].count, 2u);  // the dilated joint still pushes, its faces apart
    EXPECT_NEAR(w.contacts[0].points[0].dilation_m + w.contacts[0].points[1].dilation_m, 2.0 * dilating.rise_m,
                1e-3 * dilating.rise_m);
    // The ledger closes as well as the non-dilating run's: measured 5.5e-6 against 2.5e-6 at
    // most from 0.1 s on, 2.2e-7 against 1.0e-7 at the end; both held to 1e-5.
    EXPECT_LT(dilating.largest_balance_error, 1e-5);
    EXPECT_LT(dry.largest_balance_error, 1e-5);
}

}  // namespace
}  // namespace blockdem
