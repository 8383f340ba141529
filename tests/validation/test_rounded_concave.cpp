// Concave bodies with rounded corners (geometry/rounded_outline.hpp): only the outline's own
// corners are arcs, so a face that a cut between two convex parts meets stays straight.
//  - an L block lying on its long face, which the cut between its parts meets, on a table: the
//    face's rounded support is the whole face less the two end arcs (2 - 2r; rounding every part
//    at every corner left 2 - 4r, a groove at the seam), and the support forces are the sharp
//    model's: the weight, through the centroid (lever rule);
//  - a frictionless block sliding across the seam of a fixed L's face feels no bump: the normal
//    force stays the weight (per-length stiffness: the two parts' contacts share the block's face
//    by their lengths).
// Tolerances, and why: the support length is geometry (round-off, 1e-9); the settled forces are
// static, reached by damping (h = 0.5 or 1): 0.1% of the weight and 1 mm of lever. The sliding
// block's normal force varies only where the two points of one part's contact close up at the
// seam (their stiffness is softened there, polygon_contact.hpp: at most half a point's length of
// 1% of the face, 0.25% of the block's support), which a critically damped block of period
// close to that passage time follows with less: 0.5%.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "contact/contact_forces.hpp"
#include "support/world_helpers.hpp"
#include "validation/validation_constants.hpp"

namespace blockdem {
namespace {

using validation::g;
constexpr double r = 0.02;  // [m] the rounding radius

ContactParameters concave_joint(double h) {
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = 1e9;
    p.ks_pa_m = 5e8;
    p.mu = 0.0;
    p.h_n = h;
    p.h_s = h;
    return p;
}

Model model(std::vector<BodyDef> bodies, double h, double duration_s, double rounding_m) {
    Model m = testing::model_with(std::move(bodies), concave_joint(h), 0.0, g, duration_s);
    m.settings.dt_s.reset();
    m.settings.dt_safety = 0.3;
    m.contact.rounding_m = rounding_m;
    return m;
}

BodyDef polygon(const std::string& name, BodyKind kind, std::vector<Vec2> vertices, double mass_kg) {
    BodyDef b;
    b.name = name;
    b.kind = kind;
    b.vertices_m = std::move(vertices);
    b.mass_kg = mass_kg;
    return b;
}

struct Support {
    double normal_n = 0.0;      ///< [N] summed over the pairs of the two bodies (on b, along n)
    double moment_n_m = 0.0;    ///< [N m] of the normal forces about x = 0
    double length_m = 0.0;      ///< [m] summed tributary lengths of the points
    int pairs_touching = 0;
};

Support support(const World& w, std::uint32_t a, std::uint32_t b) {
    Support s;
    for (const PairContact& pair : w.contacts) {
        if (pair.a != a || pair.b != b || pair.count == 0) continue;
        ++s.pairs_touching;
        const ContactParameters& p = w.contact.at(w.bodies.material[a], w.bodies.material[b]);
        const JointPoint point = joint_point_of(w.bodies, pair, p, w.contact.rounding_m);
        for (std::uint32_t k = 0; k < pair.count; ++k) {
            s.normal_n += pair.points[k].normal_force_n;
            s.moment_n_m += pair.points[k].normal_force_n * pair.points[k].point_m.x;
            s.length_m += point.area_m2 / std::min(w.bodies.thickness_m[a], w.bodies.thickness_m[b]);
        }
    }
    return s;
}

// An L of two 1 m squares lying on a 2 m face that the cut between its parts meets (the parts
// are the 2 x 1 m rectangle of its other long face and the 1 m square on it): the L
// (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), cut along y = 1, turned by 90 degrees so that its face
// x = 0 lies on y = 0. Its centroid: x = 2 - 5/6 m.
std::vector<Vec2> lying_l() {
    std::vector<Vec2> turned;
    for (Vec2 v : std::vector<Vec2>{{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 1.0}, {1.0, 2.0}, {0.0, 2.0}})
        turned.push_back({2.0 - v.y, v.x});
    return turned;
}

Support settled_l(double rounding_m) {
    const double mass = 6000.0;
    std::vector<BodyDef> bodies{testing::rectangle_body("table", BodyKind::fixed, 4.0, 0.5, {1.0, -0.25}),
                                polygon("l", BodyKind::dynamic, lying_l(), mass)};
    World w = build_world(model(bodies, 0.5, 0.5, rounding_m));
    while (w.time_s < 0.5) {
        step_begin(w);
        step_end(w);
    }
    return support(w, 0, 1);
}

TEST(RoundedConcave, LOnItsSeamedFaceIsSupportedByTheWholeFaceLessTheArcs) {
    const double weight = 6000.0 * g, centroid_x = 2.0 - 2.5 / 3.0;
    const Support round = settled_l(r);
    const Support sharp = settled_l(0.0);
    RecordProperty("support_length_m", std::to_string(round.length_m));
    RecordProperty("resultant_x_m", std::to_string(round.moment_n_m / round.normal_n));
    ASSERT_EQ(round.pairs_touching, 2) << "the cut between the L's parts must meet the face it lies on";
    EXPECT_NEAR(round.length_m, 2.0 - 2.0 * r, 1e-9);
    EXPECT_NEAR(round.normal_n, weight, 1e-3 * weight);
    EXPECT_NEAR(round.moment_n_m / round.normal_n, centroid_x, 1e-3);
    EXPECT_NEAR(sharp.normal_n, weight, 1e-3 * weight);
    EXPECT_NEAR(sharp.moment_n_m / sharp.normal_n, round.moment_n_m / round.normal_n, 1e-3);
}

// A fixed L with its seamed 2 m face on top (y = 0, x from 0 to 2); a frictionless 0.4 x 0.2 m
// block of 100 kg lands on it at x = 0.4 m and slides at 1 m/s across the seam at x = 1 m.
TEST(RoundedConcave, BlockSlidingAcrossTheSeamFeelsNoBump) {
    const double mass = 100.0, weight = mass * g;
    std::vector<Vec2> upside_down;  // the lying L turned by 180 degrees, its long face on top
    for (Vec2 v : lying_l()) upside_down.push_back({2.0 - v.x, -v.y});
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.4, 0.2, {0.4, 0.1}, 0.0, mass);
    block.velocity_m_s = {1.0, 0.0};
    std::vector<BodyDef> bodies{polygon("l", BodyKind::fixed, upside_down, 1.0), block};
    World w = build_world(model(bodies, 1.0, 1.0, r));
    double worst = 0.0;
    int most_pairs = 0;
    while (w.time_s < 1.0) {
        step_begin(w);
        if (w.time_s > 0.1) {
            const Support s = support(w, 0, 1);
            worst = std::max(worst, std::abs(s.normal_n - weight) / weight);
            most_pairs = std::max(most_pairs, s.pairs_touching);
        }
        step_end(w);
    }
    RecordProperty("worst_normal_force_change", std::to_string(worst));
    EXPECT_EQ(most_pairs, 2) << "the block must cross the seam";
    EXPECT_GT(w.bodies.position_m[1].x, 1.3);
    EXPECT_LT(worst, 5e-3);
}

}  // namespace
}  // namespace blockdem
