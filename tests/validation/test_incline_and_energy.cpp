// A block on an incline (sticks below atan(mu), slides above it with g (sin a - mu cos a)), and
// conservation of energy with no damping and no sliding.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "support/world_helpers.hpp"

namespace blockdem {
namespace {

constexpr double g = 9.81;
constexpr double deg = std::numbers::pi / 180.0;

struct InclineRun {
    double displacement_m;        ///< along the slope, downhill positive, at the end
    double acceleration_m_s2;     ///< mean downhill acceleration from 0.3 s to the end
};

// A fixed 10 m x 0.5 m slab tilted by slope_rad, and a 0.2 x 0.1 m block resting on it.
InclineRun run_incline(double slope_rad, double mu, double duration) {
    const Rotation r = Rotation::from_angle(slope_rad);
    BodyDef slab = testing::rectangle_body("slab", BodyKind::fixed, 10.0, 0.5, {0, 0}, slope_rad);
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.2, 0.1, r.apply(Vec2{0.0, 0.25 + 0.05}), slope_rad);
    World w = build_world(testing::model_with({slab, block}, testing::contact(1e6, mu, 0.3, 1.0), 1e-5, g, duration));
    const Vec2 downhill = r.apply(Vec2{-1.0, 0.0});
    double v_early = 0.0;
    double t_early = 0.3;
    while (w.time_s < duration) {
        step(w);
        if (std::abs(w.time_s - t_early) < 0.5e-5) v_early = dot(w.bodies.velocity_m_s[1], downhill);
    }
    const double v_end = dot(w.bodies.velocity_m_s[1], downhill);
    return {dot(w.bodies.position_m[1] - w.bodies.initial_position_m[1], downhill), (v_end - v_early) / (duration - t_early)};
}

TEST(Incline, SticksBelowFrictionAngle) {
    const double mu = 0.5;  // friction angle 26.57 degrees
    for (double slope : {10.0, 20.0, 25.0}) {
        const InclineRun r = run_incline(slope * deg, mu, 1.0);
        // Elastic shear settles to m g sin a / (2 ks) = 1e-5 m at most; allow 3x for the transient.
        EXPECT_LT(std::abs(r.displacement_m), 3.0 * g * std::sin(slope * deg) / 2e6) << slope << " degrees";
    }
}

TEST(Incline, SlidesAboveFrictionAngleWithCoulombAcceleration) {
    const double mu = 0.5;
    for (double slope : {30.0, 35.0, 45.0}) {
        const InclineRun r = run_incline(slope * deg, mu, 1.0);
        const double expected = g * (std::sin(slope * deg) - mu * std::cos(slope * deg));
        EXPECT_NEAR(r.acceleration_m_s2, expected, 0.01 * expected) << slope << " degrees";
        std::printf("incline %.0f deg, mu = %.2f: acceleration %.5f m/s^2, g (sin a - mu cos a) = %.5f (%.3f%%)\n",
                    slope, mu, r.acceleration_m_s2, expected, 100.0 * (r.acceleration_m_s2 - expected) / expected);
    }
}

TEST(Energy, ConservedWithoutDampingOrSliding) {
    // A stack of three blocks settles with damping for 0.5 s; then damping is switched off, the
    // ledger restarts, and the table shakes at 0.1 g, 2 Hz for 3 s with mu = 10, so that no
    // corner slides or lifts: kinetic + gravitational + spring energy changes only by the
    // table's work. Bound: 0.2% of the largest term, the central difference's error at about
    // 60 steps per contact period. (Settling first matters: a contact closing from zero force
    // lets even mu = 10 slip and dissipate.)
    std::vector<BodyDef> bodies = {testing::rectangle_body("table", BodyKind::driven, 2.0, 0.2, {0, -0.1})};
    for (int i = 0; i < 3; ++i)
        bodies.push_back(testing::rectangle_body("block" + std::to_string(i), BodyKind::dynamic, 0.4, 0.2, {0, 0.1 + 0.2 * i}, 0.0, 10.0));
    Model m = testing::model_with(bodies, testing::contact(1e6, 10.0, 0.5, 1.0), 1e-5, g, 3.5);
    m.table_motion.horizontal = SineMotion{0.1 * g, 0.5, 0.0, 0.5, 0.0};
    World w = build_world(m);
    while (w.time_s < 0.5) step(w);
    for (auto& p : w.contact.parameters) p.h_n = p.h_s = 0.0;
    initialise_energy(w);
    w.energy = EnergyLedger{w.energy.kinetic_j, w.energy.gravitational_j, w.energy.elastic_j, 0, 0, 0, 0,
                            w.energy.initial_j, w.energy.initial_gravitational_j, 0.0};
    double worst = 0.0;
    bool slid = false;
    while (w.time_s < 3.5) {
        step_begin(w);
        worst = std::max(worst, w.energy.balance_error());
        for (const auto& pair : w.contacts)
            for (std::uint32_t k = 0; k < pair.count; ++k) slid = slid || pair.points[k].sliding;
        step_end(w);
    }
    EXPECT_FALSE(slid);
    EXPECT_LT(worst, 0.002);
    EXPECT_LT(w.energy.dissipated_j(), 1e-6 * w.energy.scale_j());
    std::printf("energy: largest balance error %.3g of the largest term (%.4g J); table work %.4g J\n", worst,
                w.energy.scale_j(), w.energy.table_work_j);
}

}  // namespace
}  // namespace blockdem
