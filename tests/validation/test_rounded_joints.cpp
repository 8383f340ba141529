// Joints with rounded corners ([contact] rounding with per-length stiffness and bonds) against
// closed forms:
//  - direct tension of a bonded block breaks at sigma_t A, where A is the joint's straight part
//    (the block's width less the two arcs' tangent lengths, r each for square corners: the
//    rounded narrow phase puts the joint's two points at its ends);
//  - a block balanced on one rounded corner, its centroid above the arc's centre, carries its
//    weight W on the one point with overlap W / (JKN L t): a one-point contact's tributary
//    length L is the rounding radius r, or the sharp corner's 0.1 x the least width if that is
//    larger (docs/physics.md, "Joint stiffness per unit length").
// Tolerances, and why: the loads are static or slowly ramped (inertia below 1e-3 of the load,
// as in test_joints.cpp), the overlaps those of linear springs settled by damping: 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;
constexpr double joint_rounding_m = 0.01;  // [m] the rounding radius

ContactParameters rounded_joint(double kn_pa_m, double ks_pa_m, double mu) {
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = kn_pa_m;
    p.ks_pa_m = ks_pa_m;
    p.mu = mu;
    p.h_n = 0.5;
    p.h_s = 0.5;
    return p;
}

Model rounded_model(std::vector<BodyDef> bodies, const ContactParameters& c, double duration_s, double rounding_m) {
    Model m = testing::model_with(std::move(bodies), c, 0.0, g, duration_s);
    m.settings.dt_s.reset();
    m.settings.dt_safety = 0.3;
    m.contact.rounding_m = rounding_m;
    return m;
}

struct RoundedPairLoad {
    double normal_n = 0.0;
    int points = 0;
    int intact = 0;
    double overlap_m = 0.0;  ///< [m] the first point's
};

RoundedPairLoad rounded_load_of(const World& w, std::uint32_t a, std::uint32_t b) {
    RoundedPairLoad l;
    for (const PairContact& pair : w.contacts) {
        if (pair.a != std::min(a, b) || pair.b != std::max(a, b)) continue;
        l.points += static_cast<int>(pair.count);
        if (pair.count > 0) l.overlap_m = pair.points[0].overlap_m;
        for (std::uint32_t k = 0; k < pair.count; ++k) {
            l.normal_n += pair.points[k].normal_force_n;
            l.intact += pair.points[k].bond == BondState::intact ? 1 : 0;
        }
    }
    return l;
}

// As test_joints.cpp's direct tension, with rounded corners: a 0.5 m x 0.2 m block of 100 kg
// bonded under a driven ceiling that accelerates upwards at 100 m/s^3; sigma_t = 10 kPa over
// A = (0.5 - 2 r) m x 1 m: it breaks when m (g + a) = sigma_t A = 4800 N.
TEST(RoundedJoints, BondedDirectTensionBreaksAtTensileStrengthTimesTheStraightJoint) {
    const double width = 0.5, mass = 100.0, sigma_t = 1e4;
    std::vector<BodyDef> bodies{testing::rectangle_body("ceiling", BodyKind::driven, 1.0, 0.2, {0.0, 0.1}),
                                testing::rectangle_body("block", BodyKind::dynamic, width, 0.2, {0.0, -0.1}, 0.0, mass)};
    for (BodyDef& b : bodies) b.bond_group = 1;
    ContactParameters p = rounded_joint(1e9, 5e8, 0.6);
    p.cohesion_pa = 1e5;
    p.tensile_strength_pa = sigma_t;
    p.h_n = 1.0;
    Model m = rounded_model(bodies, p, 0.6, joint_rounding_m);
    m.table_motion.vertical = make_acceleration_series({0.0, 1.0}, {0.0, 100.0});
    World w = build_world(m);
    ASSERT_EQ(rounded_load_of(w, 0, 1).intact, 2);
    double pull_at_break = NAN;
    double last_pull = 0.0;
    while (w.time_s < 0.6 && std::isnan(pull_at_break)) {
        step_begin(w);
        const RoundedPairLoad l = rounded_load_of(w, 0, 1);
        if (l.intact < 2) pull_at_break = last_pull;
        last_pull = -l.normal_n;  // n points from the ceiling (a) down to the block (b): a pull is < 0
        step_end(w);
    }
    const double area_m2 = (width - 2.0 * joint_rounding_m) * 1.0;
    RecordProperty("pull_at_break_N", std::to_string(pull_at_break));
    EXPECT_NEAR(pull_at_break, sigma_t * area_m2, 0.01 * sigma_t * area_m2);
    EXPECT_LT(w.energy.balance_error(), 1e-2);
}

// A 0.4 m x 0.8 m block of 100 kg tilted so that its centroid stands above the centre of its
// lowest corner's arc (tan(theta) = (w/2 - r) / (h/2 - r)), on a floor 1 m thick: the floor's
// reaction passes through that centre and the centroid, so the block balances on the corner
// (for the 0.5 s of the test; it is unstable, but nothing perturbs it beyond round-off). The one
// point carries W with overlap W / (JKN L t), L = max(r, 0.1 x 0.4 m).
double corner_overlap(double rounding_m, double& normal_n, double& turn_rad) {
    const double w = 0.4, h = 0.8, mass = 100.0;
    const double theta = std::atan((0.5 * w - rounding_m) / (0.5 * h - rounding_m));
    const double centre_depth = std::hypot(0.5 * w - rounding_m, 0.5 * h - rounding_m);  // centroid to arc centre
    std::vector<BodyDef> bodies{
        testing::rectangle_body("floor", BodyKind::fixed, 4.0, 1.0, {0.0, -0.5}),
        testing::rectangle_body("block", BodyKind::dynamic, w, h, {0.0, centre_depth + rounding_m}, theta, mass)};
    World world = build_world(rounded_model(bodies, rounded_joint(1e9, 5e8, 0.6), 0.5, rounding_m));
    while (world.time_s < 0.5) {
        step_begin(world);
        step_end(world);
    }
    const RoundedPairLoad l = rounded_load_of(world, 0, 1);
    EXPECT_EQ(l.points, 1);
    normal_n = l.normal_n;
    turn_rad = world.bodies.rotation_rad[1];  // (the body starts at rotation 0: its corners are drawn tilted)
    return l.overlap_m;
}

TEST(RoundedJoints, BlockOnOneRoundedCornerCarriesItsWeightWithOverlapWOverJknLT) {
    const double weight = 100.0 * g, jkn = 1e9;
    // r = 6 cm, above the sharp corner's 0.1 x 0.4 m: L = r.
    double normal = 0.0, turn = 0.0;
    const double large = corner_overlap(0.06, normal, turn);
    RecordProperty("overlap_r_6cm_m", std::to_string(large));
    EXPECT_NEAR(normal, weight, 0.01 * weight);
    EXPECT_NEAR(large, weight / (jkn * 0.06 * 1.0), 0.01 * weight / (jkn * 0.06));
    EXPECT_LT(std::abs(turn), 1e-6);  // still balanced: the test is of a standing block
    // r = 1 cm, below it: the sharp corner's L = 4 cm, as with r = 0.
    const double small = corner_overlap(0.01, normal, turn);
    RecordProperty("overlap_r_1cm_m", std::to_string(small));
    EXPECT_NEAR(small, weight / (jkn * 0.04 * 1.0), 0.01 * weight / (jkn * 0.04));
    const double sharp = corner_overlap(0.0, normal, turn);
    RecordProperty("overlap_sharp_m", std::to_string(sharp));
    EXPECT_NEAR(sharp, weight / (jkn * 0.04 * 1.0), 0.01 * weight / (jkn * 0.04));
}

}  // namespace
}  // namespace blockdem
