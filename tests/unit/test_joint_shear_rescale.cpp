// A per-length joint point keeps its shear stress when its tributary length changes
// (contact/narrow_phase.cpp, rescale_joint_shear): its kept shear spring force is scaled by
// L_new / L_old, as its normal force JKN L t (overlap + u_d) follows L by itself. Checked on a
// block teleported on its base between two narrow-phase passes (no law in between, so the
// scaling is all that changes the kept forces): an edge contact whose overlap shrinks, and an
// edge contact that turns into a corner one (L from l / 2 to 0.1 w). Per-point contacts keep
// their forces as they were.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/narrow_phase.hpp"
#include "laws/mohr_coulomb_joint.hpp"
#include "support/world_helpers.hpp"

namespace blockdem {
namespace {

// A 0.4 x 0.2 m block centred at x = centre_x_m, laid exactly on a fixed base base_width_m wide
// centred at x = 0 (top at y = 0).
Model block_on_base(double base_width_m, double centre_x_m, StiffnessBasis basis) {
    ContactParameters p;
    p.stiffness = basis;
    p.kn_pa_m = 1e10;
    p.ks_pa_m = 5e9;
    p.kn_N_m = p.ks_N_m = 1e9;
    p.mu = 0.8;
    p.h_n = p.h_s = 0.3;
    return testing::model_with({testing::rectangle_body("base", BodyKind::fixed, base_width_m, 0.2, {0.0, -0.1}),
                                testing::rectangle_body("block", BodyKind::dynamic, 0.4, 0.2, {centre_x_m, 0.1}, 0.0, 200.0)},
                               p, 1e-6, 9.81);
}

// The pair of base and block once the block is pressed 1e-6 m into the base (a narrow-phase
// pass), with shear springs of 100 and 60 N put on its two points.
std::size_t loaded_pair(World& w) {
    w.bodies.position_m[1].y -= 1e-6;
    update_body_geometry(w);
    update_contact_geometry(w);
    for (std::size_t p = 0; p < w.contacts.size(); ++p)
        if (w.contacts[p].count == 2) {
            w.contacts[p].points[0].shear_spring_n = 100.0;
            w.contacts[p].points[1].shear_spring_n = 60.0;
            return p;
        }
    ADD_FAILURE() << "no edge contact";
    return 0;
}

// Moves the block to centre c_m, turned by angle_rad, and runs the narrow phase again.
void teleport(World& w, Vec2 c_m, double angle_rad) {
    w.bodies.position_m[1] = c_m;
    w.bodies.rotation_rad[1] = angle_rad;
    update_body_geometry(w);
    update_contact_geometry(w);
}

double shear_of_feature(const PairContact& pair, std::uint32_t feature) {
    for (std::uint32_t k = 0; k < pair.count; ++k)
        if (pair.points[k].feature == feature) return pair.points[k].shear_spring_n;
    ADD_FAILURE() << "the point left";
    return NAN;
}

TEST(JointShearRescale, ShrinkingOverlapScalesTheKeptShearForces) {
    // Block and base both 0.4 m wide, the block 0.1 m off: the overlap runs from the block's left
    // corner to the base's right one, 0.3 m; sliding the block 5 mm on shrinks it to 0.295 m.
    World w = build_world(block_on_base(0.4, 0.1, StiffnessBasis::per_length));
    const std::size_t p = loaded_pair(w);
    const std::uint32_t f0 = w.contacts[p].points[0].feature;
    const std::uint32_t f1 = w.contacts[p].points[1].feature;
    teleport(w, {0.105, 0.1 - 1e-6}, 0.0);
    ASSERT_EQ(w.contacts[p].count, 2u);
    const double ratio = 0.295 / 0.3;
    EXPECT_NEAR(shear_of_feature(w.contacts[p], f0), 100.0 * ratio, 1e-9);
    EXPECT_NEAR(shear_of_feature(w.contacts[p], f1), 60.0 * ratio, 1e-9);
}

TEST(JointShearRescale, FaceTurningIntoACornerScalesItsShearForce) {
    // Turned about its right bottom corner (0.2, 0) until its left end is 1 mm up (past the
    // kept open end's 2e-4 m): one point is left, at that corner, L from 0.2 m to 0.02 m.
    World w = build_world(block_on_base(1.0, 0.0, StiffnessBasis::per_length));
    const std::size_t p = loaded_pair(w);
    const PairContact before = w.contacts[p];
    const std::uint32_t right = before.points[0].point_m.x > before.points[1].point_m.x ? 0 : 1;
    const double angle_rad = -std::asin(1e-3 / 0.4);  // clockwise: the left end rises
    const Vec2 corner{0.2, -1e-6};
    const Vec2 to_centre{-0.2, 0.1};
    const Vec2 turned{std::cos(angle_rad) * to_centre.x - std::sin(angle_rad) * to_centre.y,
                      std::sin(angle_rad) * to_centre.x + std::cos(angle_rad) * to_centre.y};
    teleport(w, corner + turned, angle_rad);
    ASSERT_EQ(w.contacts[p].count, 1u);
    const double ratio = corner_length_fraction * 0.2 / 0.2;
    EXPECT_NEAR(shear_of_feature(w.contacts[p], before.points[right].feature), before.points[right].shear_spring_n * ratio,
                1e-9);
}

TEST(JointShearRescale, PerPointContactsKeepTheirShearForces) {
    World w = build_world(block_on_base(0.4, 0.1, StiffnessBasis::per_point));
    const std::size_t p = loaded_pair(w);
    const std::uint32_t f0 = w.contacts[p].points[0].feature;
    teleport(w, {0.105, 0.1 - 1e-6}, 0.0);
    ASSERT_EQ(w.contacts[p].count, 2u);
    EXPECT_EQ(shear_of_feature(w.contacts[p], f0), 100.0);
}

}  // namespace
}  // namespace blockdem
