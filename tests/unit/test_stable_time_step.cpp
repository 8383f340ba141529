// The stable time step (dynamics/critical_time_step.hpp) against the exact eigenvalues of a
// block resting on two corners, and the run-time checks that go with it: the live contacts'
// limit and the penetration stop.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dynamics/critical_time_step.hpp"
#include "support/world_helpers.hpp"
#include "world/simulation_error.hpp"

namespace blockdem {
namespace {

// A 2b x 2h block of mass m on a fixed base, undamped: y decouples (2 kn / m); x and the
// rotation couple through the shear springs at lever h, and the normal springs at lever b
// resist the rotation. The largest eigenvalue of M^-1 K in closed form.
double exact_highest_omega_squared(double kn, double ks, double m, double inertia, double b, double h) {
    const double xx = 2.0 * ks / m;
    const double xr = 2.0 * ks * h / std::sqrt(m * inertia);
    const double rr = (2.0 * ks * h * h + 2.0 * kn * b * b) / inertia;
    const double coupled = 0.5 * (xx + rr) + std::sqrt(0.25 * (xx - rr) * (xx - rr) + xr * xr);
    return std::max(coupled, 2.0 * kn / m);
}

World resting_block(double kn, double ks, double width, double height, double h_n, double h_s) {
    BodyDef base = testing::rectangle_body("base", BodyKind::fixed, 4.0, 0.2, {0.0, -0.1});
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, width, height, {0.0, 0.5 * height}, 0.0, 100.0);
    Model m = testing::model_with({base, block}, testing::contact(kn, 0.8, h_n, h_s, ks), 1e-7, 9.81);
    return build_world(m);
}

TEST(StableTimeStep, HighestModeOfABlockOnTwoCornersMatchesTheExactEigenvalue) {
    for (const auto& [width, height] : {std::pair{0.4, 1.6}, std::pair{1.0, 0.5}, std::pair{0.6, 0.6}}) {
        const World w = resting_block(1e8, 5e7, width, height, 0.0, 0.0);
        const double m = w.bodies.mass_kg[1];
        const double exact = std::sqrt(exact_highest_omega_squared(1e8, 5e7, m, w.bodies.inertia_kg_m2[1], 0.5 * width,
                                                                   0.5 * height));
        // Undamped: the limit is 2 / omega.
        EXPECT_NEAR(w.critical_dt_s, 2.0 / exact, 1e-3 * (2.0 / exact)) << width << " x " << height;
        // The Gershgorin bound is below the exact limit, and not absurdly so.
        EXPECT_LE(w.proven_stable_dt_s, 2.0 / exact * (1.0 + 1e-12));
        EXPECT_GT(w.proven_stable_dt_s, 0.4 * 2.0 / exact);
    }
}

// One dynamic body: its own 3 x 3 blocks are the whole matrices, so the watch's per-body test
// (body_block_limit, run every 128 steps) finds the exact limit once dt is above it, and nothing
// below it.
TEST(StableTimeStep, ABodysOwnBlocksGiveItsLimitOnceDtIsAbove) {
    World w = resting_block(1e8, 5e7, 0.4, 1.6, 0.0, 0.0);
    const double m = w.bodies.mass_kg[1];
    const double exact = 2.0 / std::sqrt(exact_highest_omega_squared(1e8, 5e7, m, w.bodies.inertia_kg_m2[1], 0.2, 0.8));
    // (Placed touching, the corners press into the base under gravity within some steps.)
    for (int k = 0; k < 1000 && (w.contacts.empty() || w.contacts[0].count < 2); ++k) step(w);
    ASSERT_FALSE(w.contacts.empty());
    ASSERT_EQ(w.contacts[0].count, 2u);
    EXPECT_FALSE(std::isfinite(body_block_limit(w, 0.99 * exact).dt_s));
    const CriticalTimeStep own = body_block_limit(w, 1.01 * exact);
    EXPECT_NEAR(own.dt_s, exact, 1e-3 * exact);
    EXPECT_EQ(own.body, "block");
}

TEST(StableTimeStep, DashpotsLowerTheLimitAsForOneDampedMode) {
    const World undamped = resting_block(1e8, 1e8, 0.4, 1.6, 0.0, 0.0);
    const World damped = resting_block(1e8, 1e8, 0.4, 1.6, 0.3, 1.0);
    EXPECT_LT(damped.critical_dt_s, 0.8 * undamped.critical_dt_s);
}

// The old one-corner estimate gave 1.9e-4 s for the paper's tombstone, and a 5 g pulse
// diverged at 0.9 of it. The tombstone on two corners with h_s = 1 is limited by its base
// shear-rocking mode; at 0.95 of the new limit the run completes and its energy closes.
TEST(StableTimeStep, TombstoneUnderAFiveGPulseRunsAtNinetyFivePercentOfTheLimit) {
    BodyDef table = testing::rectangle_body("table", BodyKind::driven, 4.0, 0.2, {0.0, -0.1});
    BodyDef stone = testing::rectangle_body("tombstone", BodyKind::dynamic, 0.4, 1.6, {0.0, 0.8}, 0.0, 665.6);
    stone.inertia_kg_m2 = 150.87;
    ContactParameters c = testing::contact(1e9, 0.8, 0.4559, 1.0);
    Model m = testing::model_with({table, stone}, c, 1e-7, 9.81, 1.5);
    m.table_motion.horizontal = PulseMotion{PulseMotion::Shape::one_sine, 5.0 * 9.80665, 0.5, 0.0};
    const double limit = build_world(m).critical_dt_s;
    EXPECT_LT(limit, 1.5e-4);
    m.settings.dt_s = 0.95 * limit;
    World w = build_world(m);
    while (w.time_s < 1.5) step(w);
    EXPECT_LT(w.energy.balance_error(), 0.03);
    EXPECT_LT(w.stability.first_exceeded_s, 0.0) << "the live contacts' limit fell below dt";
}

// A block on contacts far too soft for it sinks into the table: stopped with the pair, the
// overlap and a suggested kn, not reported as a normal result.
TEST(Penetration, SinkingBlockIsStoppedWithThePairAndASuggestedStiffness) {
    BodyDef table = testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0.0, -0.1});
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.5, 0.2, {0.0, 0.1});
    World w = build_world(testing::model_with({table, block}, testing::contact(10.0, 0.3, 0.28, 1.0), 1e-4, 9.81, 5.0));
    try {
        while (w.time_s < 5.0) step(w);
        FAIL() << "the block sank through without a word";
    } catch (const SimulationError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("penetration: bodies 'table' and 'block'"), std::string::npos) << message;
        EXPECT_NE(message.find("simulation.max_overlap"), std::string::npos) << message;
        EXPECT_NE(message.find("raise kn (now 10 N/m)"), std::string::npos) << message;
    }
    EXPECT_GT(w.stability.max_overlap_ratio, 0.25);
    EXPECT_LT(w.stability.max_overlap_ratio, 0.26);
    EXPECT_GT(w.bodies.position_m[1].y, 0.0) << "stopped before it passed through";
}

// The same block on a per-length joint far too soft for it: the suggestion is a JKN in Pa/m, the
// unit the scenario's kn has then, with the point stiffness it gave (JKN L t = 40 x 0.25 x 1 =
// 10 N/m at each end of the 0.5 m face).
TEST(Penetration, PerLengthJointSuggestsAStiffnessPerUnitArea) {
    BodyDef table = testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0.0, -0.1});
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.5, 0.2, {0.0, 0.1});
    ContactParameters joint = testing::contact(10.0, 0.3, 0.28, 1.0);
    joint.stiffness = StiffnessBasis::per_length;
    joint.kn_pa_m = joint.ks_pa_m = 40.0;
    World w = build_world(testing::model_with({table, block}, joint, 1e-4, 9.81, 5.0));
    try {
        while (w.time_s < 5.0) step(w);
        FAIL() << "the block sank through without a word";
    } catch (const SimulationError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("raise kn (now 40 Pa/m per unit joint area, 10 N/m at this point) to about"),
                  std::string::npos) << message;
        EXPECT_NE(message.find(" Pa/m for an overlap near 1%"), std::string::npos) << message;
        EXPECT_EQ(message.find("N/m) to about"), std::string::npos) << message;
    }
}

TEST(Penetration, StiffContactsRecordTheirDeepestOverlap) {
    BodyDef table = testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0.0, -0.1});
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.5, 0.2, {0.0, 0.1});
    World w = build_world(testing::model_with({table, block}, testing::contact(2e4, 0.3, 0.28, 1.0), 1e-4, 9.81, 1.0));
    while (w.time_s < 1.0) step(w);
    // At rest each corner carries m g / 2: overlap 2.45e-4 m of the 0.2 m least width.
    EXPECT_NEAR(w.stability.max_overlap_m, 9.81 / 2.0 / 2e4, 0.5 * 9.81 / 2.0 / 2e4);
    EXPECT_NEAR(w.stability.max_overlap_ratio, w.stability.max_overlap_m / 0.2, 1e-12);
}

}  // namespace
}  // namespace blockdem
