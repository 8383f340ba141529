// The stable time step (dynamics/critical_time_step.hpp) against the exact eigenvalues of a
// block resting on two corners, and the run-time checks that go with it: the live contacts'
// limit and the penetration stop.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/critical_time_step.hpp"
#include "dynamics/highest_mode.hpp"
#include "dynamics/stability_rows.hpp"
#include "support/dense_pencil.hpp"
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

// The limit of the points' highest mode found densely: K~ and C~ assembled entry by entry from
// each point's relative-displacement map along its normal and its tangent (3 rows a body: x, y and
// the rotation, mass-normalised; a body that does not move has none), their pencil's limit by
// bisection over Jacobi eigenvalues (tests/support/dense_pencil.hpp).
double dense_points_limit_s(const World& w, const std::vector<StiffnessPoint>& points) {
    const std::size_t n = 3 * w.bodies.size();
    testing::DensePencil m{testing::Dense(n, std::vector<double>(n, 0.0)), testing::Dense(n, std::vector<double>(n, 0.0))};
    for (const StiffnessPoint& p : points) {
        const Vec2 directions[2] = {p.normal, perp(p.normal)};
        const double k[2] = {p.kn_N_m, p.ks_N_m}, c[2] = {p.cn_N_s_m, p.cs_N_s_m};
        for (int d = 0; d < 2; ++d) {
            std::vector<double> g(n, 0.0);
            for (const auto& [body, sign] : {std::pair{p.a, -1.0}, std::pair{p.b, 1.0}}) {
                if (w.bodies.kind[body] != BodyKind::dynamic) continue;
                const Vec2 lever = p.point_m - w.bodies.position_m[body];
                g[3 * body] = sign * directions[d].x / std::sqrt(w.bodies.mass_kg[body]);
                g[3 * body + 1] = sign * directions[d].y / std::sqrt(w.bodies.mass_kg[body]);
                g[3 * body + 2] = sign * cross(lever, directions[d]) / std::sqrt(w.bodies.inertia_kg_m2[body]);
            }
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j < n; ++j) {
                    m.k[i][j] += k[d] * g[i] * g[j];
                    m.c[i][j] += c[d] * g[i] * g[j];
                }
        }
    }
    return testing::dense_limit_s(m);
}

// Two 0.4 m blocks of 400 kg, one resting on a fixed base, the other dropped onto it from 1 cm,
// both dashpots. The start's contacts are each block's on the base (the upper one lands there, as
// far as the start can tell), whose highest mode is 1.27 times their Gershgorin bound; stacked, it
// is 2.07 times the stack's. The live watch estimates its ratio again when the scaled limit falls
// below dt on a new layout, so a dt between the start ratio's limit and the stack's own is not
// reported, and the limit it records is the stack's highest mode, found densely.
TEST(StableTimeStep, TheLiveWatchEstimatesItsRatioAgainWhenABlockLandsOnAnother) {
    const auto stack = [](double dt_s) {
        // (The run above the stack's limit is to be reported by the watch, not stopped by the
        // energy check first.)
        BodyDef base = testing::rectangle_body("base", BodyKind::fixed, 3.0, 0.2, {0.0, -0.1});
        BodyDef lower = testing::rectangle_body("lower", BodyKind::dynamic, 0.4, 0.4, {0.0, 0.2}, 0.0, 400.0);
        BodyDef upper = testing::rectangle_body("upper", BodyKind::dynamic, 0.4, 0.4, {0.0, 0.61}, 0.0, 400.0);
        Model m = testing::model_with({base, lower, upper}, testing::contact(1e7, 0.5, 0.3, 1.0), dt_s, 9.81);
        m.settings.max_energy_error = 1e9;
        return build_world(m);
    };
    // The stacked layout's limit, densely, from a run at a small dt.
    World probe = stack(1e-4);
    while (probe.time_s < 0.3) step(probe);
    const std::vector<StiffnessPoint> points = start_stiffness_points(probe);
    // Its points' dashpots are the law's, by the rule written out here: C = 2 h sqrt(k M / n), M the
    // pair's reduced mass (a block's own on the base), n its points (two corners each).
    ASSERT_EQ(points.size(), 4u);
    for (const StiffnessPoint& p : points) {
        const Bodies& b = probe.bodies;
        const bool both = b.kind[p.a] == BodyKind::dynamic && b.kind[p.b] == BodyKind::dynamic;
        const double mass_kg = both ? b.mass_kg[p.a] * b.mass_kg[p.b] / (b.mass_kg[p.a] + b.mass_kg[p.b])
                                    : (b.kind[p.a] == BodyKind::dynamic ? b.mass_kg[p.a] : b.mass_kg[p.b]);
        EXPECT_NEAR(p.cn_N_s_m, 2.0 * 0.3 * std::sqrt(1e7 * mass_kg / 2.0), 1e-9 * p.cn_N_s_m);
        EXPECT_NEAR(p.cs_N_s_m, 2.0 * 1.0 * std::sqrt(1e7 * mass_kg / 2.0), 1e-9 * p.cs_N_s_m);
    }
    const double stacked_s = dense_points_limit_s(probe, points);
    const double start_ratio = start_limit_ratio(probe.critical_dt_s, probe.stability.start_bound_s);
    EXPECT_LT(start_ratio, 1.4);
    // At 0.75 of it: below the start's limit (a block alone is less stiff), above the stack's bound
    // times the start's ratio.
    World w = stack(0.75 * stacked_s);
    ASSERT_LT(w.dt_s, w.critical_dt_s);
    while (w.time_s < 0.3) step(w);
    StabilityRows rows;
    ASSERT_GT(w.dt_s, start_ratio * live_time_step(w, rows).dt_s) << "the start's ratio alone would report this dt";
    EXPECT_LT(w.stability.first_exceeded_s, 0.0) << "reported at t = " << w.stability.first_exceeded_s;
    EXPECT_GE(w.stability.estimates, 1);
    EXPECT_NEAR(w.stability.least_limit_s, stacked_s, 5e-3 * stacked_s);
    EXPECT_NEAR(w.stability.limit_ratio, 2.1, 0.05);
    // Above the stack's limit the watch reports it.
    World fast = stack(1.1 * stacked_s);
    while (fast.time_s < 0.3) step(fast);
    EXPECT_GE(fast.stability.first_exceeded_s, 0.0);
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

// The body an unstable run's message names: the fastest, and one whose speed is not finite
// before any (the one that blew up): compared as numbers, an inf or nan speed lost to the
// table's 9e-6 m/s and the message named the table.
TEST(UnstableRunMessage, NamesTheBodyWhoseSpeedIsNotFinite) {
    const double nan = std::nan("");
    const double inf = HUGE_VAL;
    const auto fastest = [](std::vector<double> speeds_m_s) {
        return fastest_body(speeds_m_s.size(), [&](std::size_t i) { return speeds_m_s[i]; });
    };
    EXPECT_EQ(fastest({9e-6, 0.5, 0.2}), 1u);
    EXPECT_EQ(fastest({9e-6, nan, 0.2}), 1u);
    EXPECT_EQ(fastest({9e-6, 0.2, inf}), 2u);
    EXPECT_EQ(fastest({nan, 0.2, inf}), 0u);  // the first that blew up
}

}  // namespace
}  // namespace blockdem
