// The Mohr-Coulomb joint law (laws/mohr_coulomb_joint.hpp) driven through load, unload, slip,
// reversal, tension and failure against hand-computed forces.
#include <gtest/gtest.h>

#include <cmath>

#include "laws/mohr_coulomb_joint.hpp"

namespace blockdem {
namespace {

// JKN = 1e9 Pa/m, JKS = 5e8 Pa/m; a point carrying 0.1 m of a 0.2 m thick joint: A = 0.02 m^2,
// kn = 2e7 N/m, ks = 1e7 N/m. c = 1e5 Pa (c A = 2000 N), sigma_t = 5e4 Pa (sigma_t A = 1000 N).
ContactParameters joint() {
    ContactParameters p;
    p.stiffness = StiffnessBasis::per_length;
    p.kn_pa_m = 1e9;
    p.ks_pa_m = 5e8;
    p.mu = 0.6;
    p.residual_mu = 0.4;
    p.cohesion_pa = 1e5;
    p.tensile_strength_pa = 5e4;
    return p;
}

const JointPoint point = joint_point(joint(), 0.1, 0.2);
const DashpotCoefficients no_damping{0.0, 0.0};
constexpr double dt = 1e-4;

TEST(MohrCoulombJoint, StiffnessIsPerUnitAreaTimesTributaryArea) {
    EXPECT_DOUBLE_EQ(point.area_m2, 0.02);
    EXPECT_DOUBLE_EQ(point.kn_N_m, 2e7);
    EXPECT_DOUBLE_EQ(point.ks_N_m, 1e7);
    // Two points of an edge-to-edge contact carry half the overlap each; one point a tenth of
    // the thinner body's least width.
    EXPECT_DOUBLE_EQ(tributary_length_m(2, {0.0, 0.0}, {0.6, 0.8}, 0.5), 0.5);
    EXPECT_DOUBLE_EQ(tributary_length_m(1, {0.0, 0.0}, {0.0, 0.0}, 0.5), 0.05);
    EXPECT_DOUBLE_EQ(bond_opening_m(joint()), 5e-5);
}

TEST(MohrCoulombJoint, IntactBondPullsUntilTheTensileStrength) {
    // 40 um open: the spring pulls with 2e7 * 4e-5 = 800 N < sigma_t A = 1000 N: holds.
    JointForce f = mohr_coulomb_joint(joint(), point, no_damping, {-4e-5, 0.0, 0.0}, {}, BondState::intact, dt);
    EXPECT_EQ(f.bond, BondState::intact);
    EXPECT_DOUBLE_EQ(f.force.normal_n, -800.0);
    EXPECT_DOUBLE_EQ(joint_elastic_energy(point, -4e-5, 0.0, BondState::intact), 0.5 * 2e7 * 1.6e-9);
    // 60 um open: 1200 N > 1000 N: breaks in tension, pulls no more, and the 0.5 kn d^2 the
    // spring held is released.
    f = mohr_coulomb_joint(joint(), point, no_damping, {-6e-5, 0.0, 0.0}, {}, BondState::intact, dt);
    EXPECT_EQ(f.bond, BondState::broken_tension);
    EXPECT_DOUBLE_EQ(f.force.normal_n, 0.0);
    EXPECT_DOUBLE_EQ(f.bond_breakage_j, 0.5 * 2e7 * 3.6e-9);
    EXPECT_DOUBLE_EQ(joint_elastic_energy(point, -6e-5, 0.0, BondState::broken_tension), 0.0);
    // Once broken, a gap is a gap.
    f = mohr_coulomb_joint(joint(), point, no_damping, {-1e-6, 0.0, 0.0}, {}, BondState::broken_tension, dt);
    EXPECT_DOUBLE_EQ(f.force.normal_n, 0.0);
}

TEST(MohrCoulombJoint, ShearStrengthIsCohesionPlusFrictionThenResidual) {
    // Pressed 0.5 mm: F_n = 1e4 N; strength c A + mu F_n = 2000 + 6000 = 8000 N.
    const ContactKinematics pressed{5e-4, 0.0, 0.0};
    JointForce f = mohr_coulomb_joint(joint(), point, no_damping, pressed, {}, BondState::intact, dt);
    EXPECT_DOUBLE_EQ(f.force.normal_n, 1e4);
    // Load in shear: 7900 N of spring (0.79 mm), sticking.
    f = mohr_coulomb_joint(joint(), point, no_damping, {5e-4, 0.0, 7.9}, {}, BondState::intact, dt);
    EXPECT_EQ(f.bond, BondState::intact);
    EXPECT_DOUBLE_EQ(f.force.shear_spring_n, -7900.0);
    EXPECT_FALSE(f.force.sliding);
    // Unload and reverse: back by 1000 N, elastic, the bond intact.
    f = mohr_coulomb_joint(joint(), point, no_damping, {5e-4, 0.0, -1.0}, {-7900.0}, BondState::intact, dt);
    EXPECT_DOUBLE_EQ(f.force.shear_spring_n, -6900.0);
    EXPECT_EQ(f.bond, BondState::intact);
    // 1200 N more than the 8000 N strength: fails in shear; now the residual 0.4 * 1e4 = 4000 N.
    f = mohr_coulomb_joint(joint(), point, no_damping, {5e-4, 0.0, 2.3}, {-6900.0}, BondState::intact, dt);
    EXPECT_EQ(f.bond, BondState::broken_shear);
    EXPECT_TRUE(f.force.sliding);
    EXPECT_DOUBLE_EQ(f.force.shear_n, -4000.0);
    // Released: the trapezoidal work -(6900 + 4000)/2 * -2.3e-4 = 1.2535 J the bodies did, less
    // the spring's change (4000^2 - 6900^2)/(2 ks) = -1.5805 J: 2.834 J, booked as breakage.
    EXPECT_NEAR(f.bond_breakage_j, 0.5 * (6900.0 + 4000.0) * 2.3e-4 + (6900.0 * 6900.0 - 4000.0 * 4000.0) / 2e7, 1e-12);
    EXPECT_DOUBLE_EQ(f.force.friction_work_j, 0.0);
    // Sliding on: dry with the residual friction, friction dissipates.
    f = mohr_coulomb_joint(joint(), point, no_damping, {5e-4, 0.0, 1.0}, {-4000.0}, BondState::broken_shear, dt);
    EXPECT_DOUBLE_EQ(f.force.shear_n, -4000.0);
    EXPECT_NEAR(f.force.friction_work_j, 4000.0 * 1e-4, 1e-12);
    // Reversal after failure: elastic again from the residual cap.
    f = mohr_coulomb_joint(joint(), point, no_damping, {5e-4, 0.0, -2.0}, {-4000.0}, BondState::broken_shear, dt);
    EXPECT_DOUBLE_EQ(f.force.shear_spring_n, -2000.0);
    EXPECT_FALSE(f.force.sliding);
}

TEST(MohrCoulombJoint, TensionLowersTheShearStrength) {
    // Pulled with 500 N: strength c A + mu F_n = 2000 - 300 = 1700 N.
    const ContactParameters p = joint();
    JointForce f = mohr_coulomb_joint(p, point, no_damping, {-2.5e-5, 0.0, 1.69}, {}, BondState::intact, dt);
    EXPECT_EQ(f.bond, BondState::intact);
    EXPECT_DOUBLE_EQ(f.force.normal_n, -500.0);
    f = mohr_coulomb_joint(p, point, no_damping, {-2.5e-5, 0.0, 1.71}, {}, BondState::intact, dt);
    EXPECT_EQ(f.bond, BondState::broken_shear);
    EXPECT_DOUBLE_EQ(f.force.normal_n, 0.0);  // broken: no tension either
    EXPECT_DOUBLE_EQ(f.force.shear_n, 0.0);
}

TEST(MohrCoulombJoint, NeverBondedPointIsDryWithPeakFriction) {
    // No cohesion and no tension without a bond; friction mu = 0.6 on F_n = 1e4 N.
    JointForce f = mohr_coulomb_joint(joint(), point, no_damping, {5e-4, 0.0, 7.0}, {}, BondState::none, dt);
    EXPECT_EQ(f.bond, BondState::none);
    EXPECT_DOUBLE_EQ(f.force.shear_n, -6000.0);
    EXPECT_TRUE(f.force.sliding);
    f = mohr_coulomb_joint(joint(), point, no_damping, {-1e-6, 0.0, 0.0}, {}, BondState::none, dt);
    EXPECT_DOUBLE_EQ(f.force.normal_n, 0.0);
}

TEST(MohrCoulombJoint, DashpotUsesThePointStiffness) {
    ContactParameters p = joint();
    p.kn_N_m = point.kn_N_m;
    p.ks_N_m = point.ks_N_m;
    p.h_n = 0.1;
    const DashpotCoefficients c = dashpot_coefficients(p, 50.0);
    EXPECT_DOUBLE_EQ(c.cn_N_s_m, 2.0 * 0.1 * std::sqrt(50.0 * 2e7));
    // Bonded and approaching at 0.01 m/s with 10 um overlap: 200 N + C v.
    const JointForce f = mohr_coulomb_joint(joint(), point, c, {1e-5, -0.01, 0.0}, {}, BondState::intact, dt);
    EXPECT_DOUBLE_EQ(f.force.normal_n, 200.0 + c.cn_N_s_m * 0.01);
}

}  // namespace
}  // namespace blockdem
