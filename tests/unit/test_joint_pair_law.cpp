// The joint-only path (update_joint_pair_contact and apply_joint_pair_law, which the step takes
// when every material pair has per-length stiffness) against the general one
// (update_pair_contact, apply_pair_law): the same bits, pair by pair, on a shaken bonded wall
// whose bonds break, with sub-contacts (the interior points' law) and without (the lean loop of
// a pair's own points, joint_ends_law: docs/performance.md, "The bonded wall", "Joints"). And
// the step's contact pass (update_convex_contacts_and_forces: narrow phase and law in one body of
// code per pair) against the two calls per pair it stands for.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "contact/contact_forces.hpp"
#include "contact/narrow_phase.hpp"
#include "scenes/assemblies.hpp"
#include "world/parallel.hpp"
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

// What the comparison saw.
struct Seen {
    std::size_t pairs = 0, intact = 0, broken = 0, open = 0, interior = 0;
};

// The two paths on copies of a small S3 wall bonded with weak joints (cohesion 2 kPa, tension
// 1 kPa: the 0.3 g shaking breaks some; residual friction below mu) every 50 steps of 1500.
void compare_paths(std::uint32_t sub_contacts, Seen& seen) {
    Model m = scenes::bonded_wall_scene(60, 1.0);
    ContactParameters joint = m.contact.at(0, 0);
    joint.cohesion_pa = 2e3;
    joint.tensile_strength_pa = 1e3;
    joint.residual_mu = 0.5 * joint.mu;
    m.contact = MaterialPairs::uniform(joint);
    m.contact.sub_contacts = sub_contacts;
    World w = build_world(m);
    ASSERT_TRUE(every_pair_per_length(w.contact));

    for (int s = 0; s < 1500; ++s) {
        if (s % 50 == 0) {
            // This step's narrow phase on two copies, then each path's law on its copy.
            World general = w;
            World joints = w;
            prepare_pair_forces(general);
            prepare_pair_forces(joints);
            for (std::size_t p = 0; p < w.contacts.size(); ++p) {
                const OpenedPoints opened_general = update_pair_contact(general, p);
                const OpenedPoints opened_joints = update_joint_pair_contact(joints, p);
                ASSERT_EQ(opened_general.count, opened_joints.count);
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
                    seen.broken += is_broken(a.points[k].bond);
                    seen.intact += a.points[k].bond == BondState::intact;
                    seen.open += a.points[k].overlap_m < 0.0 && a.points[k].bond != BondState::intact;
                }
                if (p < general.sub_contacts.size()) {
                    ASSERT_EQ(general.sub_contacts[p].count, joints.sub_contacts[p].count);
                    for (std::uint32_t k = 0; k < general.sub_contacts[p].count; ++k)
                        ASSERT_TRUE(same_point(general.sub_contacts[p].points[k], joints.sub_contacts[p].points[k]));
                    seen.interior += general.sub_contacts[p].count;
                }
                seen.pairs += a.count > 0;
            }
        }
        step(w);
    }
    std::printf("sub_contacts %u: compared pairs %zu: points intact %zu, broken %zu, open %zu, interior %zu\n",
                sub_contacts, seen.pairs, seen.intact, seen.broken, seen.open, seen.interior);
}

// The step's contact pass against the narrow phase and the law called pair by pair (the
// joint path in a world of joints only, else the general one), summed in the same chunks: the
// same bits in every point, force slot and ledger term. Every 50 steps of 1500 of the weak
// bonded wall (bonds break), with corners sharp or rounded, per-length or per-point.
void compare_contact_pass(double rounding_m, bool per_length, std::size_t& compared) {
    Model m = scenes::bonded_wall_scene(60, 1.0);
    ContactParameters joint = m.contact.at(0, 0);
    joint.cohesion_pa = 2e3;
    joint.tensile_strength_pa = 1e3;
    joint.residual_mu = 0.5 * joint.mu;
    if (!per_length) {
        joint.stiffness = StiffnessBasis::per_point;
        joint.kn_N_m = 6e7;
        joint.ks_N_m = 6e7;
    }
    m.contact = MaterialPairs::uniform(joint);
    m.contact.rounding_m = rounding_m;
    World w = build_world(m);
    ASSERT_EQ(every_pair_per_length(w.contact), per_length);
    for (int s = 0; s < 1500; ++s) {
        if (s % 50 == 0) {
            World fused = w;
            World apart = w;
            prepare_pair_forces(fused);
            prepare_pair_forces(apart);
            const ContactEnergy e_fused = update_convex_contacts_and_forces(fused);
            const ContactEnergy e_apart = deterministic_sum(static_cast<std::ptrdiff_t>(apart.contacts.size()), [&](std::ptrdiff_t i) {
                const auto p = static_cast<std::size_t>(i);
                if (per_length) {
                    const OpenedPoints opened = update_joint_pair_contact(apart, p);
                    return apply_joint_pair_law(apart, p, apart.contacts[p].count, opened);
                }
                const OpenedPoints opened = update_pair_contact(apart, p);
                return apply_pair_law(apart, p, apart.contacts[p].count, opened);
            });
            ASSERT_TRUE(same_energy(e_fused, e_apart)) << "step " << s;
            for (std::size_t p = 0; p < w.contacts.size(); ++p) {
                const PairContact& a = fused.contacts[p];
                const PairContact& b = apart.contacts[p];
                ASSERT_EQ(a.count, b.count);
                ASSERT_TRUE(same_bits(a.normal, b.normal));
                ASSERT_EQ(a.reference, b.reference);
                ASSERT_EQ(fused.pair_forces[p].count, apart.pair_forces[p].count);
                for (std::uint32_t k = 0; k < a.count; ++k) {
                    ASSERT_TRUE(same_point(a.points[k], b.points[k])) << "pair " << p << " point " << k;
                    ASSERT_TRUE(same_bits(fused.pair_forces[p].on_b_n[k], apart.pair_forces[p].on_b_n[k]));
                    ASSERT_TRUE(same_bits(fused.pair_forces[p].torque_on_a_n_m[k], apart.pair_forces[p].torque_on_a_n_m[k]));
                    ASSERT_TRUE(same_bits(fused.pair_forces[p].torque_on_b_n_m[k], apart.pair_forces[p].torque_on_b_n_m[k]));
                }
                compared += a.count;
            }
        }
        step(w);
    }
}

TEST(JointPairLaw, ContactPassGivesThePairByPairBits) {
    for (const double rounding_m : {0.0, 0.002})
        for (const bool per_length : {true, false}) {
            std::size_t compared = 0;
            compare_contact_pass(rounding_m, per_length, compared);
            EXPECT_GT(compared, 1000u) << "rounding " << rounding_m << " per length " << per_length;
        }
}

TEST(JointPairLaw, JointPathGivesTheGeneralPathsBits) {
    // With four sub-contacts per edge joint: the interior points' path.
    Seen seen;
    compare_paths(4, seen);
    // The comparison saw every kind of point: intact, broken, and interior ones.
    EXPECT_GT(seen.pairs, 1000u);
    EXPECT_GT(seen.intact, 0u);
    EXPECT_GT(seen.broken, 0u);
    EXPECT_GT(seen.interior, 0u);
}

TEST(JointPairLaw, JointPathWithoutSubContactsGivesTheGeneralPathsBits) {
    // Without sub-contacts every pair takes the lean loop of its own points: intact, broken
    // (with the residual friction) and open ones.
    Seen seen;
    compare_paths(2, seen);
    EXPECT_GT(seen.pairs, 1000u);
    EXPECT_GT(seen.intact, 0u);
    EXPECT_GT(seen.broken, 0u);
    EXPECT_GT(seen.open, 0u);
    EXPECT_EQ(seen.interior, 0u);
}

}  // namespace
}  // namespace blockdem
