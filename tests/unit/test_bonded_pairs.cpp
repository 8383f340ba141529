// Bonds made at the start (contact/bonded_pairs.hpp) on concave bodies: a concave body is bonded
// per convex part pair that touches, as the narrow phase sees it, not along its whole outline
// (a convex-polygon test on a concave outline finds overlaps where none are).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/bonded_pairs.hpp"
#include "support/world_helpers.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

// A fixed L: a foot 1.0 x 0.2 m along the bottom and a stem 0.2 m wide up to 1.0 m on its
// left. A 0.3 x 0.3 m block of 90 kg sits in the L's inner corner against the stem's face
// (x = 0.2 m, y from 0.3 to 0.6 m), 0.1 m above the foot: it touches the stem only.
Model block_beside_an_l(std::uint32_t bond_group) {
    BodyDef l;
    l.name = "L";
    l.kind = BodyKind::fixed;
    l.vertices_m = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.2}, {0.2, 0.2}, {0.2, 1.0}, {0.0, 1.0}};
    l.density_kg_m3 = 2500.0;
    BodyDef block = testing::rectangle_body("block", BodyKind::dynamic, 0.3, 0.3, {0.35, 0.45}, 0.0, 90.0);
    l.bond_group = block.bond_group = bond_group;
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = 1e10;
    p.ks_pa_m = 4e9;
    p.mu = 0.6;
    p.h_n = p.h_s = 0.5;
    p.cohesion_pa = 1e5;  // c A = 3e4 N against the block's weight of 883 N
    p.tensile_strength_pa = 5e4;
    Model m = testing::model_with({l, block}, p, 0.0, 9.81, 0.2);
    m.settings.dt_s.reset();
    m.settings.dt_safety = 0.3;
    return m;
}

TEST(BondedPairs, ConcaveBodyIsBondedAlongThePartThatTouches) {
    World w = build_world(block_beside_an_l(1));
    const Bodies& b = w.bodies;
    ASSERT_EQ(b.part_count[0], 2u) << "the L is cut into a foot and a stem";
    int bonded_points = 0;
    for (const PairContact& pair : w.contacts) {
        int intact = 0;
        for (std::uint32_t k = 0; k < pair.count; ++k) intact += pair.points[k].bond == BondState::intact ? 1 : 0;
        bonded_points += intact;
        if (intact == 0) continue;
        // The bonded part of the L is the stem: it reaches above the foot.
        const std::uint32_t l_part = pair.a == 0 ? pair.part_a : pair.part_b;
        EXPECT_GT(b.part_box_m[l_part].hi.y, 0.5) << "bonded to the foot, which the block does not touch";
        ASSERT_EQ(pair.count, 2u);
        for (std::uint32_t k = 0; k < 2; ++k) {
            EXPECT_NEAR(pair.points[k].point_m.x, 0.2, 1e-12);
            EXPECT_NEAR(pair.points[k].overlap_m, 0.0, 1e-12);
        }
        EXPECT_NEAR(std::abs(pair.points[0].point_m.y - pair.points[1].point_m.y), 0.3, 1e-12);
    }
    EXPECT_EQ(bonded_points, 2) << "the two ends of the stem's joint, nothing on the foot";
    // The bond holds the block on the stem's face: it sags by its weight over the joint's shear
    // stiffness (m g / (JKS 0.3 m 1 m) = 7.4e-7 m), far below 1e-5 m; unbonded it falls freely
    // the 0.1 m to the foot in 0.14 s (and rebounds a little: more than 5 cm down at 0.2 s).
    while (w.time_s < 0.2) step(w);
    EXPECT_NEAR(w.bodies.position_m[1].y, 0.45, 1e-5);
    World dry = build_world(block_beside_an_l(0));
    while (dry.time_s < 0.2) step(dry);
    EXPECT_LT(dry.bodies.position_m[1].y, 0.40);
}

}  // namespace
}  // namespace blockdem
