// Rounded corners ([contact] rounding) leave the validated cases as they were: with arcs of
// r = 1e-3 x the block's size, Newmark sliding, Housner's free rocking and impact restitution,
// the restitution of flat and one-corner drops, and the static rocking onset are matched within the same tolerances as with sharp corners
// (tests/validation/test_sliding.cpp, test_rocking.cpp, whose reasons for the tolerances hold
// here unchanged), and the rounded runs stay close to the sharp ones.
//
// What rounding changes, and why it is small here: a rounded block pivots on an arc, not on a
// corner, so its pivot moves inward by r and rolls; the rocking block's static threshold
// becomes g (b - r) / (h - r) (arc centre to centroid), 0.2% below g b / h at r = 0.8 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis/housner_rocking.hpp"
#include "analysis/rigid_plastic_sliding.hpp"
#include "scenes/basic_scenes.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;

TEST(Rounding, NewmarkSlidingUnchanged) {
    // The paper's block, 0.5 x 0.2 m: r = 0.5 mm.
    double slip[2] = {};
    for (int rounded = 0; rounded < 2; ++rounded) {
        Model m = scenes::paper_sliding(1.0, 5.0);
        m.contact.rounding_m = rounded ? 0.5e-3 : 0.0;
        World w = build_world(m);
        const std::uint32_t block = w.body_id("block");
        const std::uint32_t table = w.body_id("table");
        while (w.time_s < 5.0 - 0.5e-4) step(w);
        slip[rounded] = (w.bodies.position_m[block].x - w.bodies.initial_position_m[block].x) -
                        (w.bodies.position_m[table].x - w.bodies.initial_position_m[table].x);
    }
    const auto reference = rigid_plastic_sliding(scenes::paper_sliding(1.0, 5.0).table_motion.horizontal, 0.3, g, 5.0, 1e-5);
    const double ref = reference[static_cast<std::size_t>(std::llround(5.0 / 1e-5))].relative_displacement_m;
    const double u_e = 0.3 * 1.0 * g / (2.0 * 2.0e4);
    EXPECT_NEAR(slip[1], ref, 0.02 * std::abs(ref) + u_e);  // test_sliding.cpp's tolerance
    // Face-to-face sliding sees the same two points and overlaps: the slip hardly moves.
    EXPECT_NEAR(slip[1], slip[0], 1e-3 * std::abs(ref));
    std::printf("Newmark slip after 5 cycles: rounded %.4f mm, sharp %.4f mm, rigid-plastic %.4f mm (%.2f%%)\n",
                1e3 * slip[1], 1e3 * slip[0], 1e3 * ref, 100.0 * (slip[1] - ref) / ref);
}

// test_rocking.cpp's slender block: b = 0.2, h = 0.8 m half sizes, stiff contact, e = 0.2.
constexpr double rounded_b_m = 0.2, rounded_h_m = 0.8;  // [m] the half sizes b and h
constexpr double rocking_r = 0.8e-3;  // [m] 1e-3 x the block's height

Model rounded_rocking_model(double theta0, double duration, double rounding_m) {
    const Vec2 pivot{-rounded_b_m, 0.0};
    // Rounded, the block stands on the arc of its corner: lowered so that the arc's lowest point
    // (r below the arc's centre, r in from the corner along both edges) touches the table.
    const Rotation turn = Rotation::from_angle(theta0);
    const double lowest_arc_point = turn.apply(Vec2{rounding_m, rounding_m}).y - rounding_m;
    const Vec2 center = pivot + turn.apply(Vec2{rounded_b_m, rounded_h_m}) - Vec2{0.0, lowest_arc_point};
    BodyDef block =
        testing::rectangle_body("block", BodyKind::dynamic, 2 * rounded_b_m, 2 * rounded_h_m, center, theta0, 1536.0);
    BodyDef table = testing::rectangle_body("table", BodyKind::driven, 4.0, 0.2, {0, -0.1});
    Model m = testing::model_with({table, block}, testing::contact(1.0e9, 2.0, damping_ratio_paper(0.2), 1.0), 2.0e-5, g,
                                  duration);
    m.contact.rounding_m = rounding_m;
    return m;
}

struct RockingPeaks {
    std::vector<double> theta;
    std::vector<double> impacts;
};

RockingPeaks free_rocking(double rounding_m) {
    const double alpha = std::atan(rounded_b_m / rounded_h_m);
    const double theta0 = 0.5 * alpha;
    World w = build_world(rounded_rocking_model(theta0, 4.0, rounding_m));
    std::vector<double> t, theta;
    while (w.time_s < 4.0) {
        step(w);
        t.push_back(w.time_s);
        theta.push_back(theta0 + w.bodies.rotation_rad[1]);
    }
    RockingPeaks p;
    for (std::size_t i = 1; i + 1 < theta.size(); ++i) {
        if (std::abs(theta[i]) > 1e-4 && std::abs(theta[i]) >= std::abs(theta[i - 1]) && std::abs(theta[i]) > std::abs(theta[i + 1]))
            p.theta.push_back(theta[i]);
        if (theta[i] * theta[i + 1] < 0.0) p.impacts.push_back(t[i]);
    }
    return p;
}

TEST(Rounding, HousnerFreeRockingAndImpactRestitutionUnchanged) {
    const double alpha = std::atan(rounded_b_m / rounded_h_m);
    HousnerBlock hb;
    hb.half_width_m = rounded_b_m;
    hb.half_height_m = rounded_h_m;
    hb.gravity_m_s2 = g;
    const RockingResult ref = housner_rocking(hb, RestMotion{}, 0.5 * alpha, 0.0, 4.0, 1e-5);
    std::vector<double> ref_peaks;
    for (std::size_t i = 1; i + 1 < ref.history.size(); ++i) {
        const double x = ref.history[i].theta_rad;
        if (std::abs(x) > 1e-4 && std::abs(x) >= std::abs(ref.history[i - 1].theta_rad) &&
            std::abs(x) > std::abs(ref.history[i + 1].theta_rad))
            ref_peaks.push_back(x);
    }
    const RockingPeaks sharp = free_rocking(0.0);
    const RockingPeaks round = free_rocking(rocking_r);
    ASSERT_GE(round.theta.size(), 6u);
    ASSERT_GE(round.impacts.size(), 5u);
    ASSERT_GE(ref_peaks.size(), 6u);
    ASSERT_GE(ref.impact_times_s.size(), 5u);
    auto ratio = [&](double before, double after) {
        return std::sqrt((std::cos(alpha - std::abs(after)) - std::cos(alpha)) / (std::cos(alpha - std::abs(before)) - std::cos(alpha)));
    };
    // test_rocking.cpp's tolerances: r within 0.005, peaks within 3%, impact times within 1%.
    for (std::size_t k = 0; k + 1 < 6; ++k)
        EXPECT_NEAR(ratio(round.theta[k], round.theta[k + 1]), hb.housner_restitution(), 0.005) << "impact " << k;
    for (std::size_t k = 1; k < 6; ++k) {
        EXPECT_NEAR(round.theta[k], ref_peaks[k], 0.03 * std::abs(ref_peaks[k])) << "peak " << k;
        std::printf("peak %zu: rounded %.5f rad, sharp %.5f rad, Housner %.5f rad (rounded %+.2f%%)\n", k, round.theta[k],
                    sharp.theta[k], ref_peaks[k], 100.0 * (round.theta[k] - ref_peaks[k]) / ref_peaks[k]);
    }
    for (std::size_t k = 0; k < 5; ++k)
        EXPECT_NEAR(round.impacts[k], ref.impact_times_s[k], 0.01 * ref.impact_times_s[k]) << "impact " << k;
    std::printf("impact ratio r: rounded %.4f, sharp %.4f, Housner %.4f\n", ratio(round.theta[0], round.theta[1]),
                ratio(sharp.theta[0], sharp.theta[1]), hb.housner_restitution());
}

TEST(Rounding, RockingOnsetUnchanged) {
    // The slow ramp of test_rocking.cpp (to 1.2 g b/h over 6 s); onset within its 2% of g b/h.
    const double threshold = g * rounded_b_m / rounded_h_m;
    Model m = rounded_rocking_model(0.0, 6.0, rocking_r);
    m.table_motion.horizontal = make_acceleration_series({0.0, 6.0}, {0.0, 1.2 * threshold});
    World w = build_world(m);
    double onset = -1.0;
    testing::step_until(w, 6.0, [&](const World& world) {
        if (world.time_s > 0.2 && testing::contact_points_of(world, 1) == 1) onset = world.bodies.acceleration_m_s2[0].x;
        return onset > 0.0;
    });
    ASSERT_GT(onset, 0.0) << "no uplift up to 1.2 g b/h";
    EXPECT_NEAR(onset / threshold, 1.0, 0.02);
    std::printf("rounded (r = %.1f mm) rocking onset at %.4f g b/h; arc pivot g (b - r)/(h - r) = %.4f g b/h\n",
                1e3 * rocking_r, onset / threshold,
                (rounded_b_m - rocking_r) / (rounded_h_m - rocking_r) / (rounded_b_m / rounded_h_m));
}

// test_restitution_impact.cpp's drops (no gravity, 1 m/s, kn = 1e6 N/m, dt = 1e-6 s) on a
// 0.5 x 0.2 m block rounded with r = 0.5 mm; its tolerances: 2% flat, 3% on one corner.
Model drop_model(double tilt_rad, double h_n, double rounding_m) {
    Model m = testing::model_with({testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.2, {0, -0.1}),
                                   testing::rectangle_body("block", BodyKind::dynamic, 0.5, 0.2, {0, 0.2}, tilt_rad)},
                                  testing::contact(1.0e6, 0.0, h_n, 0.0), 1.0e-6, 0.0);
    m.bodies[1].velocity_m_s = {0.0, -1.0};
    m.contact.rounding_m = rounding_m;
    return m;
}

void step_through_impact(World& w) {
    bool touched = false;
    testing::step_until(w, 0.3, [&](const World& world) {
        const int n = testing::contact_points_of(world, 1);
        if (n > 0) touched = true;
        return touched && n == 0;
    });
    ASSERT_TRUE(touched);
}

TEST(Rounding, ImpactRestitutionUnchanged) {
    const double r = 0.5e-3;
    // Flat: two points, as with sharp corners; the rebound is the requested e.
    const double e = 0.6;
    World flat = build_world(drop_model(0.0, damping_ratio_rebound(e), r));
    step_through_impact(flat);
    EXPECT_NEAR(flat.bodies.velocity_m_s[1].y, e, 0.02 * e);
    // One corner: the arc lands at its lowest point, r below the arc's centre; the corner's
    // damping ratio is h sqrt(m / m_eff) with the lever of that point (test_restitution_impact.cpp).
    const double tilt = 0.2;
    const double h = damping_ratio_rebound(e);
    World w = build_world(drop_model(tilt, h, r));
    Vec2 arc_centre{0, 1e9};
    for (Vec2 v : rectangle_vertices(0.5 - 2.0 * r, 0.2 - 2.0 * r, w.bodies.position_m[1], tilt))
        if (v.y < arc_centre.y) arc_centre = v;
    const double d = arc_centre.x - w.bodies.position_m[1].x;
    const double mass = w.bodies.mass_kg[1];
    const double m_eff = 1.0 / (1.0 / mass + d * d / w.bodies.inertia_kg_m2[1]);
    const Vec2 start = w.bodies.position_m[1];
    step_through_impact(w);
    // The lowest point of the arc now (the block has turned a little).
    const Vec2 lowest = w.bodies.position_m[1] + Rotation::from_angle(w.bodies.rotation_rad[1]).apply(arc_centre - start) - Vec2{0.0, r};
    const double point_vy = w.bodies.velocity_m_s[1].y + w.bodies.angular_velocity_rad_s[1] * (lowest - w.bodies.position_m[1]).x;
    const double expected = restitution_no_tension(h * std::sqrt(mass / m_eff));
    EXPECT_NEAR(point_vy, expected, 0.03 * expected);
    std::printf("rounded drops: flat rebound %.4f (requested %.3f); one corner %.4f, predicted %.4f\n",
                flat.bodies.velocity_m_s[1].y, e, point_vy, expected);
}

}  // namespace
}  // namespace blockdem
