// The Mohr-Coulomb joint law (laws/mohr_coulomb_joint.hpp) driven through load, unload, slip,
// reversal, tension and failure against hand-computed forces.
#include <gtest/gtest.h>

#include <algorithm>
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

// Dilation (UDEC's psi). The point is driven through given kinematics as the bodies would
// drive it; per step, the energy the bodies give it (the trapezoid of its forces over the
// step's displacements, as the central-difference scheme does) must equal what it stores more
// plus what it dissipates.
struct DilatingPoint {
    ContactParameters p;
    DashpotCoefficients c{0.0, 0.0};
    ContactHistory history;
    DilationHistory dilation;
    double overlap_m = 0.0;
    double shear_force_n = 0.0;
    double stored_j = 0.0;
    double worst_imbalance_j = 0.0;  ///< the largest per-step |given - stored change - dissipated|
    double scale_j = 0.0;            ///< the largest per-step energy given

    JointForce step(double overlap_m_now, double tangential_increment_m) {
        const double normal_speed_m_s = -(overlap_m_now - overlap_m) / dt;  // > 0 separating
        const JointForce f = mohr_coulomb_joint(p, point, c, {overlap_m_now, normal_speed_m_s, tangential_increment_m / dt},
                                                history, BondState::none, dt, dilation);
        const double given_j = 0.5 * (dilation.normal_force_n + f.force.normal_n) * (overlap_m_now - overlap_m) -
                               0.5 * (shear_force_n + f.force.shear_n) * tangential_increment_m;
        const double now_j = joint_elastic_energy(point, overlap_m_now, f.force.shear_spring_n, f.bond, f.dilation_m);
        const double dissipated_j = f.force.friction_work_j + f.force.normal_dashpot_work_j + f.force.shear_dashpot_work_j;
        worst_imbalance_j = std::max(worst_imbalance_j, std::abs(given_j - (now_j - stored_j) - dissipated_j));
        scale_j = std::max(scale_j, std::abs(given_j));
        history = history_of(f.force);
        dilation = {f.dilation_m, f.force.normal_n};
        overlap_m = overlap_m_now;
        shear_force_n = f.force.shear_n;
        stored_j = now_j;
        return f;
    }
};

// A point at the cap slipping under a fixed normal displacement (a confined joint): each step
// its spring returns to the cap, which the dilation raises, so the slider slips by the shear
// increment less what the spring takes up, du_p = ks du_s / (ks + mu kn tan(psi)), the normal
// force rises by kn tan(psi) du_p exactly, and the friction dissipates (mu - tan(psi)) F_n du_p.
// (UDEC's rule, kn tan(psi) |du_s| here, would store more in the normal spring than the slider
// dissipates: with psi = phi, mu^3 kn / ks F_n |du_s| of energy made a step: docs/physics.md.)
TEST(MohrCoulombJoint, DilationUnderFixedNormalDisplacementRaisesTheNormalForceByKnTanPsiTimesTheSlip) {
    DilatingPoint d;
    d.p = joint();
    d.p.tan_dilation = 0.5;
    d.overlap_m = 5e-4;  // kn overlap = 1e4 N
    d.dilation.normal_force_n = point.kn_N_m * d.overlap_m;
    d.history.shear_spring_n = -d.p.mu * d.dilation.normal_force_n;  // at the cap, resisting +t slip
    d.shear_force_n = d.history.shear_spring_n;
    d.stored_j = joint_elastic_energy(point, d.overlap_m, d.history.shear_spring_n, BondState::none);
    const double increment_m = 1e-4;
    const double slip_m = point.ks_N_m * increment_m / (point.ks_N_m + d.p.mu * point.kn_N_m * d.p.tan_dilation);
    EXPECT_DOUBLE_EQ(slip_m, 6.25e-5);  // ks du = 1000 N against 1e7 + 0.6 x 2e7 x 0.5 N/m
    for (int i = 0; i < 5; ++i) {
        const double last_normal_n = d.dilation.normal_force_n;
        const double last_shear_n = d.history.shear_spring_n;
        const double last_dilation_m = d.dilation.dilation_m;
        const JointForce f = d.step(5e-4, increment_m);
        EXPECT_TRUE(f.force.sliding);
        EXPECT_NEAR(f.dilation_m - last_dilation_m, d.p.tan_dilation * slip_m, 1e-15);
        EXPECT_NEAR(f.force.normal_n - last_normal_n, point.kn_N_m * d.p.tan_dilation * slip_m, 1e-8);  // 625 N
        // The slip is the increment less the spring's take-up, and the spring ends on the cap.
        EXPECT_NEAR(increment_m - (last_shear_n - f.force.shear_spring_n) / point.ks_N_m, slip_m, 1e-15);
        EXPECT_NEAR(f.force.shear_spring_n, -d.p.mu * f.force.normal_n, 1e-8);
        EXPECT_NEAR(f.force.friction_work_j,
                    (d.p.mu - d.p.tan_dilation) * 0.5 * (last_normal_n + f.force.normal_n) * slip_m, 1e-12);
    }
    EXPECT_NEAR(d.dilation.normal_force_n, 1e4 + 5 * 625.0, 1e-7);
    // Reversed slip unloads the spring into the cap: the point sticks and keeps its dilation.
    const double kept_m = d.dilation.dilation_m;
    const JointForce stuck = d.step(5e-4, -1e-6);
    EXPECT_FALSE(stuck.force.sliding);
    EXPECT_EQ(stuck.dilation_m, kept_m);
    EXPECT_LT(d.worst_imbalance_j, 1e-12 * d.scale_j);
}

// A free joint: the faces open by what the point dilated in the last step (the body rises), so
// the normal load stays and the slider's slip per step tends to the whole shear increment
// (geometrically, by the factor mu kn tan(psi) / (ks + mu kn tan(psi)) a step): the point
// dilates by tan(psi) |du_s|, UDEC's rule. The friction dissipates (mu - tan(psi)) F_n du_p a
// step, nothing for an associative joint (psi = phi).
TEST(MohrCoulombJoint, FreeJointDilatesByTanPsiTimesTheShearIncrementAndAssociativeDissipatesNothing) {
    for (const double tan_psi : {0.3, 0.6}) {
        DilatingPoint d;
        d.p = joint();
        d.p.tan_dilation = tan_psi;
        d.overlap_m = 5e-4;
        d.dilation.normal_force_n = point.kn_N_m * d.overlap_m;
        d.history.shear_spring_n = d.p.mu * d.dilation.normal_force_n;  // at the cap, resisting -t slip
        d.shear_force_n = d.history.shear_spring_n;
        d.stored_j = joint_elastic_energy(point, d.overlap_m, d.history.shear_spring_n, BondState::none);
        const double increment_m = -1e-5;
        double friction_j = 0.0, expected_j = 0.0, step_m = 0.0;
        JointForce f;
        for (int i = 0; i < 25; ++i) {
            const double before_m = d.dilation.dilation_m;
            const double last_normal_n = d.dilation.normal_force_n;
            f = d.step(5e-4 - d.dilation.dilation_m, increment_m);
            step_m = f.dilation_m - before_m;
            friction_j += f.force.friction_work_j;
            expected_j += (d.p.mu - tan_psi) * 0.5 * (last_normal_n + f.force.normal_n) * step_m / tan_psi;
        }
        EXPECT_NEAR(step_m, tan_psi * std::abs(increment_m), 1e-6 * tan_psi * std::abs(increment_m)) << tan_psi;
        // (The normal force is the load plus kn times this step's dilation, which the body has not risen by yet.)
        EXPECT_NEAR(f.force.normal_n, 1e4 + point.kn_N_m * step_m, 1e-7) << tan_psi;
        EXPECT_NEAR(friction_j, expected_j, 1e-12 * 1e4 * 25 * std::abs(increment_m)) << tan_psi;
        if (tan_psi == d.p.mu) EXPECT_NEAR(friction_j, 0.0, 1e-12 * 1e4 * 25 * std::abs(increment_m));
        EXPECT_LT(d.worst_imbalance_j, 1e-12 * d.scale_j);
    }
}

// Loading, slip both ways, unloading and reloading, with dashpots: the per-step balance closes
// to round-off; the dilation never falls, and grows only on steps that slide; without
// dilation the law is the plain dry point.
TEST(MohrCoulombJoint, DilatingPointBalancesItsWorkEveryStep) {
    DilatingPoint d;
    d.p = joint();
    d.p.tan_dilation = 0.4;
    d.c = {4e4, 2e4};
    double grew = 0;
    for (int i = 1; i <= 400; ++i) {
        const double overlap_m = 2e-4 + 1.5e-4 * std::sin(0.031 * i);
        const double increment_m = 3e-5 * std::sin(0.047 * i + 0.3);
        const double before_m = d.dilation.dilation_m;
        const JointForce f = d.step(overlap_m, increment_m);
        EXPECT_GE(f.dilation_m, before_m);
        if (f.dilation_m > before_m) {
            ++grew;
            EXPECT_TRUE(f.force.sliding);
        }
    }
    EXPECT_GT(grew, 50);
    EXPECT_LT(d.worst_imbalance_j, 1e-11 * d.scale_j);
    // psi = 0: what the dry joint gives, bit for bit, whatever u_d is passed.
    const ContactKinematics k{3e-4, 0.01, 0.5};
    const JointForce plain = mohr_coulomb_joint(joint(), point, d.c, k, {900.0, 5.0, 1.0}, BondState::none, dt);
    const JointForce zero = mohr_coulomb_joint(joint(), point, d.c, k, {900.0, 5.0, 1.0}, BondState::none, dt, {1e-3, 7e3});
    EXPECT_EQ(plain.force.normal_n, zero.force.normal_n);
    EXPECT_EQ(plain.force.shear_n, zero.force.shear_n);
    EXPECT_EQ(plain.force.friction_work_j, zero.force.friction_work_j);
    EXPECT_EQ(zero.dilation_m, 0.0);
}

// dilation_zero_slip z: the dilation stops at tan(psi) z.
TEST(MohrCoulombJoint, DilationStopsAfterTheZeroDilationSlip) {
    DilatingPoint d;
    d.p = joint();
    d.p.tan_dilation = 0.5;
    d.p.dilation_zero_slip_m = 1e-4;
    d.overlap_m = 5e-4;
    d.dilation.normal_force_n = point.kn_N_m * d.overlap_m;
    d.history.shear_spring_n = d.p.mu * d.dilation.normal_force_n;
    d.shear_force_n = d.history.shear_spring_n;
    d.stored_j = joint_elastic_energy(point, d.overlap_m, d.history.shear_spring_n, BondState::none);
    for (int i = 0; i < 40; ++i) d.step(5e-4 - d.dilation.dilation_m, -1e-5);
    EXPECT_DOUBLE_EQ(d.dilation.dilation_m, 0.5 * 1e-4);
    EXPECT_NEAR(d.dilation.normal_force_n, 1e4, 1e-7);
    EXPECT_LT(d.worst_imbalance_j, 1e-12 * d.scale_j);
}

}  // namespace
}  // namespace blockdem
