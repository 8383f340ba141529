// A block on an incline (sticks below atan(mu), slides above it with g (sin a - mu cos a)), and
// conservation of energy with no damping and no sliding.
//
// Settled starts ([settling], friction held): a block placed touching a slope, stepped from
// there, first falls onto it and slips while its contacts load (the release transient); the
// rigid-plastic reference starts in equilibrium. Settled with friction held, it starts loaded in
// place: on a 20 deg slope with mu = 0.5 it does not move at all from t = 0, and under a shaking
// table it follows Newmark's incline solution; on a slope steeper than atan(mu) it slides from
// the first step with g (sin a - mu cos a) t^2 / 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "analysis/rigid_plastic_sliding.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"
#include "world/settling.hpp"
#include "world/simulation_error.hpp"

namespace blockdem {
namespace {

using validation::g;
using validation::deg;

struct InclineRun {
    double displacement_m;        ///< along the slope, downhill positive, at the end
    double acceleration_m_s2;     ///< mean downhill acceleration from 0.3 s to the end
};

// A fixed 10 m x 0.5 m slab tilted by slope_rad, and a 0.2 x 0.1 m block placed touching it;
// settled first (friction held) when `settling` is given.
Model incline_model(double slope_rad, double mu, double duration, std::optional<SettlingSettings> settling = {}) {
    const Rotation r = Rotation::from_angle(slope_rad);
    BodyDef slab = testing::rectangle_body("slab", BodyKind::fixed, 10.0, 0.5, {0, 0}, slope_rad);
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.2, 0.1, r.apply(Vec2{0.0, 0.25 + 0.05}), slope_rad);
    Model m = testing::model_with({slab, block}, testing::contact(1e6, mu, 0.3, 1.0), 1e-5, g, duration);
    m.settling = settling;
    return m;
}

InclineRun run_incline(double slope_rad, double mu, double duration) {
    const Rotation r = Rotation::from_angle(slope_rad);
    World w = build_world(incline_model(slope_rad, mu, duration));
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

// The block's largest displacement along the slope and largest speed over `duration` from t = 0.
struct Transient {
    double peak_displacement_m = 0.0;  ///< [m] |downhill displacement| from where t = 0 found it
    double peak_speed_m_s = 0.0;       ///< [m/s]
};

Transient release_transient(World& w, double slope_rad, double duration) {
    const Vec2 downhill = Rotation::from_angle(slope_rad).apply(Vec2{-1.0, 0.0});
    const Vec2 start = w.bodies.position_m[1];
    Transient t;
    while (w.time_s < duration) {
        step(w);
        t.peak_displacement_m = std::max(t.peak_displacement_m, std::abs(dot(w.bodies.position_m[1] - start, downhill)));
        t.peak_speed_m_s = std::max(t.peak_speed_m_s, length(w.bodies.velocity_m_s[1]));
    }
    return t;
}

// Below the friction angle (20 deg, mu = 0.5, atan(mu) = 26.6 deg): placed touching, the block
// falls onto the slope and slips while its contacts load; settled with friction held, it is in
// equilibrium at t = 0 and does not move. Bound: 1e-9 m, far below the unsettled transient (of
// order the elastic shear m g sin a / ks = 3.4e-6 m) and above round-off of a settled state.
TEST(Incline, SettledBlockBelowFrictionAngleStartsInEquilibrium) {
    const double slope = 20.0 * deg;
    World unsettled = build_world(incline_model(slope, 0.5, 0.5));
    const Transient before = release_transient(unsettled, slope, 0.5);
    World settled = build_world(incline_model(slope, 0.5, 0.5, SettlingSettings{1e-10, 0.05, 2.0}));
    ASSERT_TRUE(settled.settling);
    EXPECT_TRUE(settled.settling->friction_held);
    const Transient after = release_transient(settled, slope, 0.5);
    SettlingSettings actual{1e-10, 0.05, 2.0};
    actual.friction = SettlingFriction::actual;
    World settled_actual = build_world(incline_model(slope, 0.5, 0.5, actual));
    const Transient after_actual = release_transient(settled_actual, slope, 0.5);
    std::printf("20 deg incline settled with friction \"actual\": transient %.3g m (%.3g m/s)\n",
                after_actual.peak_displacement_m, after_actual.peak_speed_m_s);
    std::printf("20 deg incline, mu = 0.5: release transient %.3g m (peak speed %.3g m/s) unsettled; %.3g m (%.3g m/s) "
                "after %.3g s of settling (which moved the block %.3g m)\n",
                before.peak_displacement_m, before.peak_speed_m_s, after.peak_displacement_m, after.peak_speed_m_s,
                settled.settling->time_s, settled.settling->largest_move_m);
    EXPECT_GT(before.peak_displacement_m, 1e-6);
    EXPECT_LT(after.peak_displacement_m, 1e-9);
    EXPECT_LT(after.peak_speed_m_s, 1e-6);
}

// Above the friction angle (30 deg, mu = 0.5): settled with friction held, the block starts with
// its contacts loaded and slides from the first step with the Coulomb acceleration: slip =
// g (sin a - mu cos a) t^2 / 2 from t = 0, to 0.2% (what settling leaves of its velocity,
// kinetic energy < 1e-10 m g L, is 1.5e-5 m/s, 0.07% of the slip at 0.1 s; the contact springs
// relax from the held shear to mu N in the first steps). With friction "actual" the same block
// cannot be settled at all: it slides while settling.
TEST(Incline, SettledBlockAboveFrictionAngleSlidesFromTheFirstStep) {
    const double slope = 30.0 * deg;
    const double mu = 0.5;
    const double a = g * (std::sin(slope) - mu * std::cos(slope));
    for (const bool settle_first : {false, true}) {
        World w = build_world(incline_model(slope, mu, 0.5, settle_first ? std::optional(SettlingSettings{1e-10, 0.05, 2.0})
                                                                         : std::nullopt));
        const Vec2 downhill = Rotation::from_angle(slope).apply(Vec2{-1.0, 0.0});
        const Vec2 start = w.bodies.position_m[1];
        double worst = 0.0;
        for (const double t : {0.1, 0.2, 0.5}) {
            while (w.time_s < t - 0.5e-5) step(w);
            const double slip = dot(w.bodies.position_m[1] - start, downhill);
            const double expected = 0.5 * a * t * t;
            worst = std::max(worst, std::abs(slip - expected) / expected);
            std::printf("30 deg incline, %s: slip at %.1f s %.6g m, g (sin a - mu cos a) t^2 / 2 = %.6g m (%+.3f%%)\n",
                        settle_first ? "settled" : "unsettled", t, slip, expected, 100.0 * (slip - expected) / expected);
        }
        if (settle_first) EXPECT_LT(worst, 0.002);
    }
    SettlingSettings actual{1e-10, 0.05, 2.0};
    actual.friction = SettlingFriction::actual;
    EXPECT_THROW(build_world(incline_model(slope, mu, 0.5, actual)), SimulationError);
}

// The final slip of the settled block on the tilted, shaken table against Newmark's; returns Newmark's.
double compare_with_newmark(double slope, double mu, const SineMotion& shaking) {
    double slip_m[2] = {0.0, 0.0};
    const std::vector<SlidingPoint> reference =
        rigid_plastic_sliding(ComponentMotion{shaking}, incline_surface(mu, slope, g), 2.5, 1e-5);
    const double newmark_m = reference.back().relative_displacement_m;
    for (const bool settle_first : {false, true}) {
        Model m = testing::model_with({testing::rectangle_body("table", BodyKind::driven, 2.0, 0.2, {0, -0.1}),
                                       testing::rectangle_body("block", BodyKind::dynamic, 0.2, 0.1, {0, 0.05})},
                                      testing::contact(1e6, mu, 0.3, 1.0), 0.0, g, 2.5);
        m.settings.dt_s.reset();
        m.settings.tilt_rad = slope;
        m.table_motion.horizontal = shaking;
        if (settle_first) m.settling = SettlingSettings{1e-10, 0.05, 2.0};
        World w = build_world(m);
        while (w.time_s < 2.5) step(w);
        slip_m[settle_first] = (w.bodies.position_m[1].x - w.bodies.initial_position_m[1].x) -
                               (w.bodies.position_m[0].x - w.bodies.initial_position_m[0].x);
        std::printf("20 deg tilted table, A = %g m/s^2, T = 0.5 s, 4 cycles, %s: final slip %.6g m, Newmark %.6g m "
                    "(%+.3f%%)\n",
                    shaking.amplitude_m_s2, settle_first ? "settled" : "unsettled", slip_m[settle_first], newmark_m,
                    100.0 * (slip_m[settle_first] - newmark_m) / std::abs(newmark_m));
    }
    EXPECT_NEAR(slip_m[1], newmark_m, 0.005 * std::abs(newmark_m)) << "A = " << shaking.amplitude_m_s2;
    return newmark_m;
}

// A settled block on a table tilted by 20 deg (gravity turned, geometry level), shaken along the
// table's surface by a = A sin(2 pi t / T), against Newmark's rigid-plastic block on an incline
// (rigid_plastic_sliding with incline_surface): it yields down the slope when the table
// accelerates up it by more than g (mu cos a - sin a) = 1.25 m/s^2 and up the slope beyond
// g (mu cos a + sin a) = 7.96 m/s^2: at A = 3 m/s^2 it ratchets down the slope only, at
// A = 9 m/s^2 it slips both ways, more down than up. Tolerance on
// the final slip: 0.5% (the contact springs, 1e6 N/m on a 1 kg block, smear each stick-slip
// transition over the shear spring's period, about 4 ms, twice a cycle; measured 0.02%).
TEST(Incline, SettledBlockOnTiltedTableFollowsNewmark) {
    const double slope = 20.0 * deg;
    const double mu = 0.5;
    for (const double amplitude : {3.0, 9.0}) {
        const double newmark_m = compare_with_newmark(slope, mu, SineMotion{amplitude, 0.5, 0.0, 0.0, 4.0});
        EXPECT_LT(newmark_m, -0.01);  // down the slope (-x), by centimetres
    }
}

// The reference itself on a steep incline with the table at rest: it slides from t = 0 with
// g (sin a - mu cos a) down the slope (-s), to the trapezoid's round-off.
TEST(Incline, NewmarkReferenceSlidesDownASteepIncline) {
    const std::vector<SlidingPoint> r = rigid_plastic_sliding(ComponentMotion{RestMotion{}}, incline_surface(0.5, 30.0 * deg, g), 1.0, 1e-3);
    const double a = g * (std::sin(30.0 * deg) - 0.5 * std::cos(30.0 * deg));
    EXPECT_NEAR(r.back().relative_displacement_m, -0.5 * a, 1e-9);
    EXPECT_NEAR(r.back().block_acceleration_m_s2, -a, 1e-12);
    // Below the friction angle it stays.
    EXPECT_EQ(rigid_plastic_sliding(ComponentMotion{RestMotion{}}, incline_surface(0.5, 20.0 * deg, g), 1.0, 1e-3)
                  .back()
                  .relative_displacement_m,
              0.0);
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
