// The summary's definitions: overturned (beyond the critical angle at the end), rocked, slid
// (base slip, not centroid motion), for level and tilted starts.
#include <gtest/gtest.h>

#include <cmath>

#include "support/world_helpers.hpp"
#include "world/response_monitor.hpp"

namespace blockdem {
namespace {

constexpr double b = 0.2, h = 0.8;  // half sizes [m]

struct Outcome {
    BodyResponse response;
    double final_rotation_rad;
};

Outcome run(double tilt_rad, const ComponentMotion& table, double duration) {
    const Vec2 pivot{-b, 0.0};
    const Vec2 center = pivot + Rotation::from_angle(tilt_rad).apply(Vec2{b, h});
    Model m = testing::model_with({testing::rectangle_body("table", BodyKind::driven, 4.0, 0.2, {0, -0.1}),
                                   testing::rectangle_body("block", BodyKind::dynamic, 2 * b, 2 * h, center, tilt_rad, 1536.0)},
                                  testing::contact(1e9, 0.8, damping_ratio_paper(0.2), 1.0), 2e-5, 9.81, duration);
    m.table_motion.horizontal = table;
    World w = build_world(m);
    ResponseMonitor monitor(w);
    while (w.time_s < duration) {
        step_begin(w);
        monitor.observe(w);
        step_end(w);
    }
    return {monitor.responses()[1], w.bodies.rotation_rad[1]};
}

// w run to its duration, observed at every step.
ResponseMonitor observed_run(World& w) {
    ResponseMonitor monitor(w);
    while (w.time_s < w.settings.duration_s) {
        step_begin(w);
        monitor.observe(w);
        step_end(w);
    }
    return monitor;
}

TEST(ResponseMonitor, ABlockTouchingNothingIsNamedInAWarning) {
    // The block 1 m above the table for 0.2 s falls 0.2 m and meets nothing; on the table it
    // touches at once. Only the first gets the warning (the summary's; io/summary_writer.cpp).
    for (const double lift_m : {1.0, 0.0}) {
        Model m = testing::model_with({testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0, -0.1}),
                                       testing::rectangle_body("block", BodyKind::dynamic, 2 * b, 2 * h, {0.0, h + lift_m}, 0.0, 1536.0)},
                                      testing::contact(1e9, 0.8, 0.3, 1.0), 2e-5, 9.81, 0.2);
        World w = build_world(m);
        const ResponseMonitor monitor = observed_run(w);
        const std::vector<std::string> warnings = untouched_body_warnings(monitor.records(w), w.bodies.name, w.time_s);
        if (lift_m > 0.0) {
            ASSERT_EQ(warnings.size(), 1u);
            EXPECT_NE(warnings[0].find("body 'block' touched no other body in the run's"), std::string::npos) << warnings[0];
        } else {
            EXPECT_TRUE(warnings.empty()) << warnings[0];
        }
    }
}

TEST(ResponseMonitor, AStackRestingOnNothingFixedIsNamedInAWarning) {
    // Two blocks stacked beside the table (x = 10 m) fall together for 0.3 s: they touch each
    // other, not the ground, and the lower one was reported stable after falling 0.44 m. Stacked
    // on the table, the same two rest on it through the lower one: no warning.
    for (const double x_m : {10.0, 0.0}) {
        Model m = testing::model_with({testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0, -0.1}),
                                       testing::rectangle_body("lower", BodyKind::dynamic, 0.4, 0.4, {x_m, 0.2}, 0.0, 2000.0),
                                       testing::rectangle_body("upper", BodyKind::dynamic, 0.4, 0.4, {x_m, 0.6}, 0.0, 2000.0)},
                                      testing::contact(1e8, 0.6, 0.3, 1.0), 2e-5, 9.81, 0.3);
        World w = build_world(m);
        const ResponseMonitor monitor = observed_run(w);
        const std::vector<BodyRecord> records = monitor.records(w);
        const std::vector<std::string> warnings = untouched_body_warnings(records, w.bodies.name, w.time_s);
        if (x_m > 0.0) {
            ASSERT_TRUE(records[1].touched_a_body && records[2].touched_a_body);
            ASSERT_EQ(warnings.size(), 2u);
            EXPECT_NE(warnings[0].find("body 'lower' touched other bodies but never rested, directly or through them, on a "
                                       "fixed or driven body in the run's"),
                      std::string::npos)
                << warnings[0];
            EXPECT_NE(warnings[1].find("body 'upper' touched other bodies"), std::string::npos) << warnings[1];
        } else {
            EXPECT_TRUE(records[1].rested_on_ground && records[2].rested_on_ground);
            EXPECT_TRUE(warnings.empty()) << warnings[0];
        }
    }
}

TEST(ResponseMonitor, LevelBlockCriticalAngles) {
    Model m = testing::model_with({testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0, -0.1}),
                                   testing::rectangle_body("block", BodyKind::dynamic, 2 * b, 2 * h, {0.0, h}, 0.0, 1536.0)},
                                  testing::contact(1e9, 0.8, 0.3, 1.0), 2e-5, 9.81);
    const ResponseMonitor monitor(build_world(m));
    EXPECT_NEAR(monitor.responses()[1].alpha_ccw_rad, std::atan(b / h), 1e-12);
    EXPECT_NEAR(monitor.responses()[1].alpha_cw_rad, std::atan(b / h), 1e-12);
}

TEST(ResponseMonitor, TiltedStartThatFallsBackIsNotOverturned) {
    // Released leaning 0.1 rad on its left corner (below alpha = 0.245): it falls back and rocks.
    const Outcome o = run(0.1, RestMotion{}, 2.0);
    EXPECT_NEAR(o.response.base_tilt_rad, 0.1, 1e-9);
    EXPECT_FALSE(o.response.overturned());
    EXPECT_TRUE(o.response.rocked());
    // (Its heel lands hard enough to slip about 2 mm at mu = 0.8: sliding is not asserted here.)
}

TEST(ResponseMonitor, TiltedStartBeyondAlphaOverturns) {
    const Outcome o = run(0.3, RestMotion{}, 2.0);
    EXPECT_TRUE(o.response.overturned());
    EXPECT_GT(o.final_rotation_rad, 1.0);
    EXPECT_NEAR(o.response.last_crossing_s, 0.0, 1e-9);  // it started beyond and never came back
}

TEST(ResponseMonitor, RockingWithoutSlidingIsNotSliding) {
    // Housner's 0.3 g one-sine pulse: rocks to 0.1 rad and recovers, mu = 0.8 > b/h.
    const Outcome o = run(0.0, PulseMotion{PulseMotion::Shape::one_sine, 0.3 * 9.81, 1.0, 0.0}, 4.0);
    EXPECT_TRUE(o.response.rocked());
    EXPECT_FALSE(o.response.overturned());
    EXPECT_FALSE(o.response.slid()) << "base slip " << o.response.peak_abs_base_slip_m << " m";
    EXPECT_GT(o.response.peak_abs_relative_displacement_m, 0.05);  // the centroid did move
}

}  // namespace
}  // namespace blockdem
