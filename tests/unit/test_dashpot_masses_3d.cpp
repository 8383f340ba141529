// A contact point's dashpot mass (world/world_3d.hpp, point_dashpot_masses_kg): the step keeps only
// its pair's M / S (ContactPairSums3d), and the stable bound and `blockdem check` make each point's
// M w / S again from the table. It must be the mass the step's law damps with, to the bit, and a
// pair's points must share its reduced mass M in all.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scenes/brick_wall_3d.hpp"
#include "world/step_3d.hpp"

namespace blockdem {
namespace {

TEST(DashpotMasses3d, AreTheStepsMassesAndSharePairsReducedMass) {
    // A shaken 3-course wall on its base: bricks on bricks (two dynamic bodies) and on the base
    // (one), corners with shares below 1 where the joints are staggered.
    scenes::BrickWall3dDef def;
    def.courses = 3;
    def.bricks_per_course = 8;
    def.shaking = SineMotion{15.0, 0.02, 0.0, 0.0, 0.0};
    World3d w = scenes::brick_wall_3d(def);
    for (int i = 0; i < 60; ++i) step_3d(w);
    const std::vector<double> masses_kg = point_dashpot_masses_kg(w, w.contacts);
    ASSERT_EQ(masses_kg.size(), w.contacts.size());
    std::size_t pairs_on_base = 0, pairs_of_bricks = 0, partial_shares = 0;
    for (const ContactPairSums3d& pair : w.scratch.contact_pairs) {
        ASSERT_GT(pair.points, 0u);
        const ContactPoint3d& first = w.contacts[pair.first_point];
        const double reduced_kg = pair_reduced_mass_kg(w, first.key.body_a, first.key.body_b);
        const bool on_base = w.kinds[first.key.body_a] != BodyKind3d::dynamic || w.kinds[first.key.body_b] != BodyKind3d::dynamic;
        pairs_on_base += on_base;
        pairs_of_bricks += !on_base;
        // One brick on the base damps with the brick's mass, two bricks with half of one's.
        const double brick_kg = w.bodies[on_base && w.kinds[first.key.body_a] != BodyKind3d::dynamic ? first.key.body_b : first.key.body_a].mass_kg;
        EXPECT_DOUBLE_EQ(reduced_kg, on_base ? brick_kg : 0.5 * brick_kg);
        double sum_kg = 0.0;
        for (std::uint32_t k = pair.first_point; k < pair.first_point + pair.points; ++k) {
            const ContactPoint3d& p = w.contacts[k];
            EXPECT_EQ(p.key.body_a, first.key.body_a);
            EXPECT_EQ(p.key.body_b, first.key.body_b);
            // The law's dashpot mass at the point: its share times the pair's M / S, as stored.
            if (pair.dashpot_mass_per_share_kg > 0.0)
                EXPECT_EQ(masses_kg[k], p.stiffness_share * pair.dashpot_mass_per_share_kg) << "point " << k;
            partial_shares += p.stiffness_share < 1.0;
            sum_kg += masses_kg[k];
        }
        EXPECT_NEAR(sum_kg, reduced_kg, 1e-12 * reduced_kg);
    }
    EXPECT_GT(pairs_on_base, 0u);
    EXPECT_GT(pairs_of_bricks, 0u);
    EXPECT_GT(partial_shares, 0u);
}

TEST(DashpotMasses3d, APairWithNoStiffnessSharesItsMassEqually) {
    // Shares all zero (S = 0): each of the n points takes M / n, as the step's rule says.
    scenes::BrickWall3dDef def;
    def.courses = 1;
    def.bricks_per_course = 1;
    World3d w = scenes::brick_wall_3d(def);
    for (int i = 0; i < 20; ++i) step_3d(w);
    ASSERT_FALSE(w.contacts.empty());
    std::vector<ContactPoint3d> table = w.contacts;
    for (ContactPoint3d& p : table) p.stiffness_share = 0.0;
    const std::vector<double> masses_kg = point_dashpot_masses_kg(w, table);
    for (std::size_t k = 0; k < table.size(); ++k) {
        const std::uint32_t a = table[k].key.body_a, b = table[k].key.body_b;
        std::size_t n = 0;  // the pair's points (a run of the sorted table)
        for (const ContactPoint3d& p : table) n += p.key.body_a == a && p.key.body_b == b;
        EXPECT_EQ(masses_kg[k], pair_reduced_mass_kg(w, a, b) / static_cast<double>(n)) << "point " << k;
    }
}

}  // namespace
}  // namespace blockdem
