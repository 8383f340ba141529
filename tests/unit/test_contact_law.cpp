// The linear spring-dashpot-slider driven through load, unload, slip and reversal against
// hand-computed forces.
#include <gtest/gtest.h>

#include <cmath>

#include "laws/linear_spring_dashpot.hpp"

namespace blockdem {
namespace {

ContactParameters params() {
    ContactParameters p;
    p.kn_N_m = 1000.0;
    p.ks_N_m = 500.0;
    p.mu = 0.5;
    p.h_n = 0.2;
    p.h_s = 0.0;
    return p;
}

TEST(ContactLaw, DashpotCoefficientsFromDampingRatio) {
    const DashpotCoefficients c = dashpot_coefficients(params(), 4.0);
    EXPECT_DOUBLE_EQ(c.cn_N_s_m, 2.0 * 0.2 * std::sqrt(4.0 * 1000.0));
    EXPECT_DOUBLE_EQ(c.cs_N_s_m, 0.0);
}

TEST(ContactLaw, NormalSpringAndDashpotWithoutTension) {
    const ContactParameters p = params();
    const DashpotCoefficients c{10.0, 0.0};
    // Loading: 1 mm overlap approaching at 0.1 m/s: 1000 * 0.001 + 10 * 0.1 = 2 N.
    EXPECT_DOUBLE_EQ(linear_spring_dashpot(p, c, {1e-3, -0.1, 0.0}, ContactHistory{0.0}, 1e-4).normal_n, 2.0);
    // Unloading at 0.05 m/s: 1 - 0.5 = 0.5 N.
    EXPECT_DOUBLE_EQ(linear_spring_dashpot(p, c, {1e-3, 0.05, 0.0}, ContactHistory{0.0}, 1e-4).normal_n, 0.5);
    // Fast unloading would pull: no tension, the force is zero.
    const ContactForce f = linear_spring_dashpot(p, c, {1e-3, 0.2, 0.0}, ContactHistory{0.0}, 1e-4);
    EXPECT_DOUBLE_EQ(f.normal_n, 0.0);
    // The dashpot then only cancelled the spring (-1 N). A new contact had no dashpot force at
    // the last step, so over this interval the mean dashpot force is -0.5 N: 0.5 * 0.2 * dt.
    EXPECT_DOUBLE_EQ(f.normal_dashpot_n, -1.0);
    EXPECT_NEAR(f.normal_dashpot_work_j, 0.5 * 1.0 * 0.2 * 1e-4, 1e-15);
}

TEST(ContactLaw, ShearSpringIncrementSlipAndReversal) {
    const ContactParameters p = params();
    const DashpotCoefficients c{0.0, 0.0};
    const double dt = 1e-3;
    const ContactKinematics pressed{2e-3, 0.0, 0.0};  // F_n = 2 N, cap mu F_n = 1 N
    // Stick: 0.4 m/s for one step: increment -500 * 0.4e-3 = -0.2 N.
    ContactForce f = linear_spring_dashpot(p, c, {2e-3, 0.0, 0.4}, ContactHistory{0.0}, dt);
    EXPECT_DOUBLE_EQ(f.shear_spring_n, -0.2);
    EXPECT_FALSE(f.sliding);
    // Continue: -0.2 - 1.0 = -1.2 N beyond the cap: slides at -1 N. Over the 2 mm increment the
    // mean force is -0.6 N (1.2 mJ of work) and the spring stores 0.96 mJ more: 0.24 mJ is lost.
    f = linear_spring_dashpot(p, c, {2e-3, 0.0, 2.0}, ContactHistory{-0.2}, dt);
    EXPECT_TRUE(f.sliding);
    EXPECT_DOUBLE_EQ(f.shear_spring_n, -1.0);
    EXPECT_DOUBLE_EQ(f.shear_n, -1.0);
    EXPECT_NEAR(f.friction_work_j, 0.6 * 2e-3 - (1.0 - 0.04) / 1000.0, 1e-15);
    // Reversal: moving back at 1 m/s unloads the spring elastically: -1 + 0.5 = -0.5 N, sticking.
    f = linear_spring_dashpot(p, c, {2e-3, 0.0, -1.0}, ContactHistory{-1.0}, dt);
    EXPECT_FALSE(f.sliding);
    EXPECT_DOUBLE_EQ(f.shear_spring_n, -0.5);
    (void)pressed;
}

TEST(ContactLaw, FallingNormalForceReleasesShearBeyondTheCap) {
    const ContactParameters p = params();
    // Spring at 0.8 N; the overlap drops to 1 mm: cap 0.5 N; the excess energy goes to friction.
    const ContactForce f = linear_spring_dashpot(p, {0.0, 0.0}, {1e-3, 0.0, 0.0}, ContactHistory{0.8}, 1e-3);
    EXPECT_TRUE(f.sliding);
    EXPECT_DOUBLE_EQ(f.shear_spring_n, 0.5);
    EXPECT_NEAR(f.friction_work_j, 0.5 * (0.64 - 0.25) / 500.0, 1e-15);
}

TEST(ContactLaw, ShearDashpotWhileSticking) {
    ContactParameters p = params();
    p.h_s = 1.0;
    const DashpotCoefficients c{0.0, 20.0};
    // Spring -0.05 N, dashpot -20 * 0.1 = -2 N: total capped at mu F_n = 1 N.
    const ContactForce f = linear_spring_dashpot(p, c, {2e-3, 0.0, 0.1}, ContactHistory{0.0}, 1e-3);
    EXPECT_FALSE(f.sliding);
    EXPECT_DOUBLE_EQ(f.shear_spring_n, -0.05);
    EXPECT_DOUBLE_EQ(f.shear_n, -1.0);
}

// Over any history (loading, slip, reversal, dashpots, the force dropping and the no-tension
// clamp), the work the point's forces do on the bodies, taken as the mean of the forces at the
// two ends of each interval times the interval's displacement (what the central-difference
// scheme does to the bodies), equals minus the change of stored energy minus the dissipation
// the law reports, to round-off: the ledger cannot drift whatever dt is.
TEST(ContactLaw, DissipationClosesTheWorkBalanceOverAnyHistory) {
    ContactParameters p = params();
    p.h_s = 1.0;
    const DashpotCoefficients c{30.0, 40.0};
    const double dt = 1e-3;
    double overlap = 0.0, normal = 0.0, shear = 0.0, work = 0.0, dissipated = 0.0;
    ContactHistory history;
    bool slid = false, clamped = false;
    for (int n = 0; n < 400; ++n) {
        // Approach, then pressing and sliding back and forth, then fast separation.
        const double vn = n < 50 ? -0.05 : (n < 350 ? 0.004 * std::sin(0.05 * n) : 0.05);
        const double vt = 0.8 * std::sin(0.03 * n) + 0.3 * std::cos(0.17 * n);
        overlap -= vn * dt;
        if (overlap <= 0.0) break;
        const ContactForce f = linear_spring_dashpot(p, c, {overlap, vn, vt}, history, dt);
        work += 0.5 * (normal + f.normal_n) * vn * dt + 0.5 * (shear + f.shear_n) * vt * dt;
        dissipated += f.normal_dashpot_work_j + f.shear_dashpot_work_j + f.friction_work_j;
        EXPECT_GE(f.friction_work_j, -1e-15) << "step " << n;
        slid = slid || f.sliding;
        clamped = clamped || f.normal_n == 0.0;
        normal = f.normal_n;
        shear = f.shear_n;
        history = history_of(f);
    }
    const double stored = contact_elastic_energy(p, overlap, history.shear_spring_n);
    EXPECT_TRUE(slid);
    EXPECT_TRUE(clamped);
    EXPECT_GT(dissipated, 1e-4);
    EXPECT_NEAR(work + stored + dissipated, 0.0, 1e-12 * dissipated);
}

TEST(ContactLaw, ElasticEnergy) {
    EXPECT_DOUBLE_EQ(contact_elastic_energy(params(), 1e-3, 1.0), 0.5 * 1000.0 * 1e-6 + 0.5 * 1.0 / 500.0);
}

}  // namespace
}  // namespace blockdem
