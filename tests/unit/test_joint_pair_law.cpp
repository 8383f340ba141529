// The joint-only law path (apply_joint_pair_law, which the step takes when every material pair
// has per-length stiffness) against the general one (apply_pair_law): the same bits, pair by
// pair, on a shaken bonded wall with sub-contacts whose bonds break (docs/performance.md, "The
// bonded wall").
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "contact/contact_forces.hpp"
#include "contact/narrow_phase.hpp"
#include "scenes/assemblies.hpp"
#include "world/step.hpp"

namespace blockdem {
namespace {

// Bit-for-bit equality of two plain values (a NaN equals itself, +0 and -0 differ).
template <class T>
bool same_bits(const T& x, const T& y) {
    return std::memcmp(&x, &y, sizeof(T)) == 0;
}

bool same_point(const ContactPoint& x, const ContactPoint& y) {
    return x.feature == y.feature && x.sliding == y.sliding && x.bond == y.bond && same_bits(x.point_m, y.point_m) &&
           same_bits(x.overlap_m, y.overlap_m) && same_bits(x.normal_force_n, y.normal_force_n) &&
           same_bits(x.shear_spring_n, y.shear_spring_n) && same_bits(x.shear_force_n, y.shear_force_n) &&
           same_bits(x.normal_dashpot_n, y.normal_dashpot_n) && same_bits(x.shear_dashpot_n, y.shear_dashpot_n) &&
           same_bits(x.dilation_m, y.dilation_m);
}

bool same_energy(const ContactEnergy& x, const ContactEnergy& y) {
    return same_bits(x.normal_dashpot_j, y.normal_dashpot_j) && same_bits(x.shear_dashpot_j, y.shear_dashpot_j) &&
           same_bits(x.friction_j, y.friction_j) && same_bits(x.bond_breakage_j, y.bond_breakage_j) &&
           same_bits(x.elastic_j, y.elastic_j) && same_bits(x.deepest_overlap_ratio, y.deepest_overlap_ratio) &&
           x.deepest_pair == y.deepest_pair;
}

TEST(JointPairLaw, JointPathGivesTheGeneralPathsBits) {
    // A small S3 wall bonded with weak joints (cohesion 2 kPa, tension 1 kPa: the 0.3 g shaking
    // breaks some) and four sub-contacts per edge joint.
    Model m = scenes::bonded_wall_scene(60, 1.0);
    ContactParameters joint = m.contact.at(0, 0);
    joint.cohesion_pa = 2e3;
    joint.tensile_strength_pa = 1e3;
    const std::uint32_t sub_contacts = 4;
    m.contact = MaterialPairs::uniform(joint);
    m.contact.sub_contacts = sub_contacts;
    World w = build_world(m);
    ASSERT_TRUE(every_pair_per_length(w.contact));

    std::size_t compared_pairs = 0, broken_points = 0, intact_points = 0, interior_points = 0;
    for (int s = 0; s < 1500; ++s) {
        if (s % 50 == 0) {
            // This step's narrow phase on two copies, then each path's law on its copy.
            World general = w;
            World joints = w;
            prepare_pair_forces(general);
            prepare_pair_forces(joints);
            for (std::size_t p = 0; p < w.contacts.size(); ++p) {
                const OpenedPoints opened_general = update_pair_contact(general, p);
                const OpenedPoints opened_joints = update_pair_contact(joints, p);
                const ContactEnergy e_general =
                    apply_pair_law(general, p, general.contacts[p].count, opened_general);
                const ContactEnergy e_joints = apply_joint_pair_law(joints, p, joints.contacts[p].count, opened_joints);
                ASSERT_TRUE(same_energy(e_general, e_joints)) << "pair " << p << " at step " << s;
                const PairContact& a = general.contacts[p];
                const PairContact& b = joints.contacts[p];
                ASSERT_EQ(a.count, b.count);
                ASSERT_EQ(general.pair_forces[p].count, joints.pair_forces[p].count);
                for (std::uint32_t k = 0; k < a.count; ++k) {
                    ASSERT_TRUE(same_point(a.points[k], b.points[k])) << "pair " << p << " point " << k;
                    ASSERT_TRUE(same_bits(general.pair_forces[p].on_b_n[k], joints.pair_forces[p].on_b_n[k]));
                    ASSERT_TRUE(same_bits(general.pair_forces[p].torque_on_a_n_m[k], joints.pair_forces[p].torque_on_a_n_m[k]));
                    ASSERT_TRUE(same_bits(general.pair_forces[p].torque_on_b_n_m[k], joints.pair_forces[p].torque_on_b_n_m[k]));
                    broken_points += is_broken(a.points[k].bond);
                    intact_points += a.points[k].bond == BondState::intact;
                }
                if (p < general.sub_contacts.size()) {
                    ASSERT_EQ(general.sub_contacts[p].count, joints.sub_contacts[p].count);
                    for (std::uint32_t k = 0; k < general.sub_contacts[p].count; ++k)
                        ASSERT_TRUE(same_point(general.sub_contacts[p].points[k], joints.sub_contacts[p].points[k]));
                    interior_points += general.sub_contacts[p].count;
                }
                compared_pairs += a.count > 0;
            }
        }
        step(w);
    }
    // The comparison saw every kind of point: intact, broken, and interior ones.
    EXPECT_GT(compared_pairs, 1000u);
    EXPECT_GT(intact_points, 0u);
    EXPECT_GT(broken_points, 0u);
    EXPECT_GT(interior_points, 0u);
    std::printf("compared pairs %zu: points intact %zu, broken %zu, interior %zu\n", compared_pairs, intact_points,
                broken_points, interior_points);
}

}  // namespace
}  // namespace blockdem
