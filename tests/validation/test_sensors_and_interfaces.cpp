// Sensors and interfaces (world/sensor.hpp, world/interface_monitor.hpp) on cases with known
// answers: an LVDT on a sliding block against Newmark's rigid-plastic slip, the interface's
// accumulated slip against the block's displacement relative to the table, an accelerometer on
// a block that moves with the table, and the normal forces of a drum column at rest; and the
// slid verdict judged on the body below.
//
// Tolerances, and why:
// - LVDT vs Newmark: as in test_sliding.cpp, 2% of the slip plus the elastic shear deformation
//   u_e = mu m g / (2 ks) = 74 um, which the springy DEM block carries and the rigid one does not.
// - accumulated slip vs relative displacement: both integrate the same motion, one from the
//   velocity at t (the mean of the leapfrog's half steps), the other from positions; they differ
//   by the velocity change over a step times dt (about mu g dt^2 per stick-slip transition) and by
//   the few steps at the start before the block touches (placed at zero overlap): 1e-5 m.
// - drum column at rest: the weight above each interface to 1e-4 (the springs' vibration after
//   settling with h_n = 0.3 over 60 periods of the vertical mode is far below that).
// - accelerometer on a block that sticks: both filtered at 20 Hz, 4th order, so the shear
//   spring's rattle (~25 Hz at ks = 2e4 N/m, damped) is cut as a real channel would; the block
//   follows the table to 3% of the peak table acceleration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "analysis/rigid_plastic_sliding.hpp"
#include "scenes/basic_scenes.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"
#include "world/interface_monitor.hpp"
#include "world/response_monitor.hpp"
#include "world/sensor.hpp"

namespace blockdem {
namespace {

using validation::g;

TEST(SensorsAndInterfaces, LvdtAndAccumulatedSlipOfASlidingBlock) {
    const Model m = scenes::paper_sliding(1.0, 5.0);
    World w = build_world(m);
    const std::uint32_t block = w.body_id("block");
    const std::uint32_t table = w.body_id("table");
    // The LVDT: the block's lower-left corner relative to the table point under it at the start.
    SensorBank sensors({{"lvdt", SensorKind::relative, block, {-0.25, -0.1}, table, {-0.25, 0.1}, 0.0, 4}}, w.dt_s);
    InterfaceMonitor interfaces(InterfaceSelection{true, {}});
    const auto reference = rigid_plastic_sliding(m.table_motion.horizontal, 0.3, g, 5.0, 1e-5);
    const double u_e = 0.3 * 1.0 * g / (2.0 * 2.0e4);
    double worst_slip_error = 0.0, peak_relative = 0.0;
    std::size_t next_check = 0;
    const double checks[] = {1.0, 5.0};
    while (true) {
        step_begin(w);
        sensors.observe(w);
        interfaces.observe(w);
        const Bodies& b = w.bodies;
        // The middle of the block's base (where the slip is measured; the centroid would add
        // h/2 times the block's small tilt) relative to the table.
        const double base_middle_x = b.position_m[block].x + Rotation::from_angle(b.rotation_rad[block]).apply({0.0, -0.1}).x;
        const double relative_x = (base_middle_x - b.initial_position_m[block].x) -
                                  (b.position_m[table].x - b.initial_position_m[table].x);
        peak_relative = std::max(peak_relative, std::abs(relative_x));
        // (Placed at zero overlap, the block touches from the second step on.)
        ASSERT_EQ(interfaces.interfaces().size(), w.step_index == 0 ? 0u : 1u) << "step " << w.step_index;
        const InterfaceState s = w.step_index == 0 ? InterfaceState{table, block} : interfaces.interfaces()[0];
        EXPECT_EQ(s.body_a, table);   // the lower body: +x slip is the block moving to +x on it
        worst_slip_error = std::max(worst_slip_error, std::abs(s.slip_m - relative_x));
        if (next_check < 2 && w.time_s >= checks[next_check] - 1e-9) {
            const double ref = reference[static_cast<std::size_t>(std::llround(checks[next_check] / 1e-5))].relative_displacement_m;
            const double lvdt = sensors.values()[0];
            EXPECT_NEAR(lvdt, ref, 0.02 * std::abs(ref) + u_e) << "after " << checks[next_check] << " cycles";
            std::printf("t = %.4f s, after %.0f cycle(s): LVDT %.4f mm, interface slip %.4f mm, Newmark rigid-plastic %.4f mm\n",
                        w.time_s, checks[next_check], 1e3 * lvdt, 1e3 * s.slip_m, 1e3 * ref);
            ++next_check;
        }
        if (w.time_s >= 5.0 - 1e-9) break;
        step_end(w);
    }
    EXPECT_EQ(next_check, 2u);
    EXPECT_GT(peak_relative, 50.0 * u_e);   // it did slide: the comparison means something
    EXPECT_LT(worst_slip_error, 1e-5) << "accumulated slip vs displacement relative to the table";
    const InterfaceState& s = interfaces.interfaces()[0];
    EXPECT_NEAR(s.peak_abs_slip_m, peak_relative, 1e-5);
    std::printf("accumulated slip vs relative displacement: worst difference %.3g m over a peak of %.4f m\n",
                worst_slip_error, peak_relative);
}

TEST(SensorsAndInterfaces, AccelerometerOnABlockThatSticksReadsTheTable) {
    Model m = scenes::paper_sliding(1.0, 3.0);
    const double amplitude = 0.5 * 0.3 * g;   // half of mu g: the block sticks
    m.table_motion.horizontal = SineMotion{amplitude, 0.5, 0.0, 0.0, 0.0};
    World w = build_world(m);
    const std::uint32_t block = w.body_id("block");
    const std::uint32_t table = w.body_id("table");
    SensorBank sensors({{"block", SensorKind::point, block, {0.0, 0.1}, 0, {}, 20.0, 4},
                        {"table", SensorKind::point, table, {0.0, 0.1}, 0, {}, 20.0, 4}},
                       w.dt_s);
    double worst = 0.0, raw_table_peak = 0.0;
    while (w.time_s < 3.0) {
        step_begin(w);
        sensors.observe(w);
        if (w.time_s > 0.5) {   // the drop onto the table at t = 0 and the filters' start have died out
            worst = std::max(worst, std::abs(sensors.values()[0] - sensors.values()[6]));
            raw_table_peak = std::max(raw_table_peak, std::abs(w.bodies.acceleration_m_s2[table].x));
        }
        step_end(w);
    }
    EXPECT_NEAR(raw_table_peak, amplitude, 1e-3 * amplitude);
    EXPECT_LT(worst, 0.03 * amplitude) << "filtered block vs table acceleration";
    std::printf("sticking block: filtered block and table accelerations differ by %.3g m/s^2 at most (table %.3g m/s^2)\n",
                worst, amplitude);
}

TEST(SensorsAndInterfaces, DrumColumnNormalForcesAreTheWeightAbove) {
    ContactParameters c = testing::contact(1.0e8, 0.7, 0.3, 0.3);
    Model m = scenes::block_stack(3, 0.6, 0.9, 2500.0, c, 1.0);
    World w = build_world(m);
    const std::uint32_t base = w.body_id("base");
    const std::uint32_t d[3] = {w.body_id("block0"), w.body_id("block1"), w.body_id("block2")};
    InterfaceMonitor interfaces(InterfaceSelection{false, {{base, d[0]}, {d[0], d[1]}, {d[1], d[2]}}});
    while (w.time_s < 1.0) {
        step_begin(w);
        interfaces.observe(w);
        step_end(w);
    }
    step_begin(w);
    interfaces.observe(w);
    const double weight_n = w.bodies.mass_kg[d[0]] * w.settings.gravity_m_s2;
    for (int k = 0; k < 3; ++k) {
        const InterfaceState& s = interfaces.interfaces()[static_cast<std::size_t>(k)];
        const double above_n = (3 - k) * weight_n;
        EXPECT_TRUE(s.touching);
        EXPECT_EQ(s.points, 2u);
        EXPECT_NEAR(s.normal_force_n, above_n, 1e-4 * above_n) << "interface " << k;
        EXPECT_NEAR(s.shear_force_n, 0.0, 1e-6 * above_n) << "interface " << k;
        EXPECT_LT(s.opening_m, 1e-9) << "interface " << k;
        EXPECT_LT(s.peak_abs_slip_m, 1e-9) << "interface " << k;
        std::printf("interface %d: N = %.2f N, weight above %.2f N\n", k, s.normal_force_n, above_n);
    }
}

TEST(SensorsAndInterfaces, RockingBlockOpensItsFarCorner) {
    // A block tilted on one corner: the far corner's height is the opening, w sin(theta).
    ContactParameters c = testing::contact(1.0e6, 0.8, 0.3, 0.3);
    const double width = 0.2, height = 0.6, tilt = 0.1;
    BodyDef table = testing::rectangle_body("table", BodyKind::fixed, 2.0, 0.2, {0.0, -0.1});
    const Vec2 pivot{-0.1, 0.0};   // the left base corner, on the table; the right one lifts
    const Vec2 centre = pivot + Rotation::from_angle(tilt).apply(Vec2{0.5 * width, 0.5 * height});
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, width, height, centre, tilt, 5.0);
    World w = build_world(testing::model_with({table, block}, c, 1e-5, 9.81, 0.1));
    InterfaceMonitor interfaces(InterfaceSelection{true, {}});
    step_begin(w);
    interfaces.observe(w);
    step_end(w);
    step_begin(w);
    interfaces.observe(w);
    ASSERT_EQ(interfaces.interfaces().size(), 1u);
    const InterfaceState& s = interfaces.interfaces()[0];
    EXPECT_EQ(s.points, 1u);
    EXPECT_NEAR(s.opening_m, width * std::sin(tilt), 1e-6);
}

// Two blocks on a table: the lower one slides on the table (mu 0.2), the upper one rides on it
// (mu 0.8 between the blocks). The upper block moves on the table as much as the lower, but it
// did not slide: it is judged on the body below it.
TEST(SensorsAndInterfaces, BlockRidingOnASlidingBlockDidNotSlide) {
    Model m;
    m.settings.duration_s = 2.0;
    m.settings.dt_s = 1e-4;
    m.contact.materials = {"steel", "stone"};
    m.contact.parameters.resize(4);
    m.contact.set(0, 1, testing::contact(1.0e6, 0.2, 0.3, 0.3));
    m.contact.set(1, 1, testing::contact(1.0e6, 0.8, 0.3, 0.3));
    m.contact.set(0, 0, testing::contact(1.0e6, 0.2, 0.3, 0.3));
    BodyDef table = testing::rectangle_body("table", BodyKind::driven, 4.0, 0.2, {0.0, -0.1});
    table.material = "steel";
    table.density_kg_m3 = 1000.0;
    BodyDef lower = testing::rectangle_body("lower", BodyKind::dynamic, 0.4, 0.4, {0.0, 0.2}, 0.0, 10.0);
    BodyDef upper = testing::rectangle_body("upper", BodyKind::dynamic, 0.4, 0.4, {0.0, 0.6}, 0.0, 10.0);
    lower.material = upper.material = "stone";
    m.bodies = {table, lower, upper};
    m.table_motion.horizontal = SineMotion{0.4 * g, 0.5, 0.0, 0.0, 0.0};
    World w = build_world(m);
    ResponseMonitor monitor(w);
    while (w.time_s < m.settings.duration_s) {
        step_begin(w);
        monitor.observe(w);
        step_end(w);
    }
    const BodyResponse& lo = monitor.responses()[w.body_id("lower")];
    const BodyResponse& up = monitor.responses()[w.body_id("upper")];
    std::printf("lower: base slip %.4f m (threshold %.3g m); upper: base slip %.3g m (threshold %.3g m)\n",
                lo.peak_abs_base_slip_m, lo.slip_threshold(), up.peak_abs_base_slip_m, up.slip_threshold());
    EXPECT_TRUE(lo.slid());
    EXPECT_FALSE(up.slid()) << "the upper block rode on the lower one";
    EXPECT_FALSE(up.rocked());
    EXPECT_EQ(up.support_body, static_cast<std::int64_t>(w.body_id("lower")));
    EXPECT_EQ(lo.support_body, static_cast<std::int64_t>(w.body_id("table")));
    EXPECT_GE(up.slip_threshold(), elastic_slip_factor * up.peak_elastic_shear_m);
}

}  // namespace
}  // namespace blockdem
