// The rocking calibration (study/rocking_calibration.hpp): r from a decay of peaks, the DEM's
// free-rocking restitution against Housner's, and the fit of h_n to a target r.
//
// The DEM runs use kn = 1e8 N/m on 0.2 m wide concrete blocks (480 kg a metre of thickness for
// aspect 5): static overlap m g / kn under 0.05 mm, a contact frequency far above the rocking
// one (p = 3.8 rad/s), and dt derived as a run derives it, so each run is a few thousand steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "laws/restitution.hpp"
#include "study/rocking_calibration.hpp"

namespace blockdem {
namespace {

RockingBlock concrete_block(double aspect, ContactTermination termination) {
    RockingBlock b;
    b.width_m = 0.2;
    b.height_m = 0.2 * aspect;
    b.density_kg_m3 = 2400.0;
    b.contact.kn_N_m = 1.0e8;
    b.contact.ks_N_m = 1.0e8;
    b.contact.mu = 0.8;
    b.contact.h_s = 1.0;
    b.contact.termination = termination;
    b.release_tilt_rad = 0.5 * b.alpha_rad();
    return b;
}

// Peaks of rigid rocking that loses r^2 of its energy at every impact.
std::vector<double> rigid_peaks(double alpha, double theta0, double r, int impacts) {
    std::vector<double> peaks = {theta0};
    for (int k = 0; k < impacts; ++k) {
        const double gain = r * r * (std::cos(alpha - peaks.back()) - std::cos(alpha));
        peaks.push_back(alpha - std::acos(std::cos(alpha) + gain));
    }
    return peaks;
}

// A block rocks on its corners only if it is slender enough for Housner's r to be positive
// (width / height < sqrt 2); its friction is judged by the fitted run (r >= 1 at an impact).
TEST(RockingCalibration, ObstaclesToRocking) {
    RockingBlock b = concrete_block(3.0, ContactTermination::no_tension);  // width / height = 1/3
    b.contact.mu = 0.8;
    EXPECT_EQ(rocking_obstacle(b), RockingObstacle::none);
    b.contact.mu = 0.2;  // below b/h: a free-rocking block needs less (an impact about 0.6 to 0.75 b/h)
    EXPECT_EQ(rocking_obstacle(b), RockingObstacle::none);
    b.contact.mu = 100.0;
    b.height_m = b.width_m / 1.4143;  // just above sqrt 2: Housner's r < 0
    EXPECT_EQ(rocking_obstacle(b), RockingObstacle::too_squat);
    b.height_m = b.width_m / 1.4141;
    EXPECT_EQ(rocking_obstacle(b), RockingObstacle::none);
    b.height_m = b.width_m * 0.1;  // 2 x 0.2 m, the probe's block: r = -0.485, too squat before mu counts
    EXPECT_EQ(rocking_obstacle(b), RockingObstacle::too_squat);
}

// An impact with r >= 1 gained energy: the block did not rock rigidly (the probe's mu = 0.05 fit
// read 0.333, 1.233, 1.250).
TEST(RockingCalibration, EnergyGainingImpactIsFound) {
    FreeRocking run;
    run.impact_restitution = {0.33264, 1.23319, 1.25006};
    EXPECT_EQ(first_energy_gaining_impact(run), 1);
    run.impact_restitution = {0.9, 0.95, 1.0};
    EXPECT_EQ(first_energy_gaining_impact(run), 2);
    run.impact_restitution = {0.85, 0.86};
    EXPECT_EQ(first_energy_gaining_impact(run), -1);
}

TEST(RockingCalibration, RestitutionFromPeaksInvertsRigidRocking) {
    const double alpha = std::atan(0.2);
    const std::vector<double> peaks = rigid_peaks(alpha, 0.15, 0.9, 4);
    const std::vector<double> r = restitution_from_peaks(alpha, peaks);
    ASSERT_EQ(r.size(), 4u);
    for (double x : r) EXPECT_NEAR(x, 0.9, 1e-12);
    EXPECT_NEAR(geometric_mean({0.8, 0.9}), std::sqrt(0.72), 1e-15);
    EXPECT_NEAR(housner_restitution(std::atan(1.0 / 3.0)), 0.85, 1e-12);  // sin^2 = 1/10
}

TEST(RockingCalibration, InelasticContactLosesHousnersShare) {
    // A strongly damped heel (no bounce) loses what Housner's plastic impact about the new corner
    // loses: r = 1 - 1.5 sin^2 alpha, within 1% for slender blocks.
    for (double aspect : {3.0, 5.0}) {
        RockingBlock b = concrete_block(aspect, ContactTermination::no_tension);
        b.contact.h_n = 0.9;
        const FreeRocking run = free_rocking(b);
        const double housner = housner_restitution(b.alpha_rad());
        ASSERT_EQ(run.impact_restitution.size(), 3u);
        EXPECT_FALSE(run.overturned);
        EXPECT_NEAR(run.restitution, housner, 0.01 * housner) << "aspect " << aspect;
        std::printf("aspect %g, h_n = 0.9 no_tension: DEM r = %.4f, Housner %.4f (%lld steps, dt %.3g s)\n", aspect,
                    run.restitution, housner, run.steps, run.dt_s);
    }
}

TEST(RockingCalibration, HousnersRFoundAtAnInelasticHeel) {
    // Asked for Housner's r itself, the fit lands where the heel no longer bounces: h_n of 0.3
    // or more, a head-on restitution (paper's meaning) of 0.37 or less.
    const RockingBlock b = concrete_block(5.0, ContactTermination::no_tension);
    const double housner = housner_restitution(b.alpha_rad());
    const RockingFit fit = calibrate_rocking(b, CalibratedParameter::h_n, housner, 1e-3);
    ASSERT_TRUE(fit.found);
    EXPECT_GE(fit.contact.h_n, 0.3);
    std::printf("Housner's r = %.4f: h_n = %.4f (paper e = %.3f), r = %.4f, %d runs\n", housner, fit.contact.h_n,
                restitution_paper(fit.contact.h_n),
                fit.achieved_restitution, fit.dem_runs);
}

TEST(RockingCalibration, FitRecoversTheDampingThatMadeTheTarget) {
    // Round trip: the r the DEM gives at a known h_n is fitted back to that h_n.
    for (ContactTermination rule : {ContactTermination::no_tension, ContactTermination::zero_overlap}) {
        RockingBlock b = concrete_block(5.0, rule);
        const double made_h = 0.37;
        b.contact.h_n = made_h;
        const double target = free_rocking(b).restitution;
        b.contact.h_n = 0.0;  // (not read: h_n is what the fit sets)
        const RockingFit fit = calibrate_rocking(b, CalibratedParameter::h_n, target, 1e-4);
        ASSERT_TRUE(fit.found) << to_string(rule) << ": reachable " << fit.reachable_min << " to " << fit.reachable_max;
        EXPECT_NEAR(fit.achieved_restitution, target, 1e-4);
        EXPECT_NEAR(fit.residual, fit.achieved_restitution - target, 1e-15);
        EXPECT_EQ(fit.dem_runs, static_cast<int>(fit.scan.size()));
        EXPECT_LT(fit.dem_runs, 30);
        // The fitted run is a real run with the fitted contact.
        b.contact = fit.contact;
        EXPECT_NEAR(free_rocking(b).restitution, fit.achieved_restitution, 1e-12);
        std::printf("%s: target r = %.6f (made with h_n = %.3f), fitted h_n = %.5f, r = %.6f, %d runs\n", to_string(rule),
                    target, made_h, fit.contact.h_n, fit.achieved_restitution, fit.dem_runs);
    }
}

TEST(RockingCalibration, ShakeTableValuesAreReachable) {
    // Concrete blocks of aspect 3 and 5 rock with about 0.95 to 0.97 of Housner's r on shake
    // tables. A stiff no-tension contact cannot go below Housner's r (the test above); with the
    // paper's termination and kn = 1e7 N/m (0.14 and 0.24 mm of static overlap) h_n reaches them.
    for (double aspect : {3.0, 5.0}) {
        RockingBlock b = concrete_block(aspect, ContactTermination::zero_overlap);
        b.contact.kn_N_m = b.contact.ks_N_m = 1.0e7;
        const double housner = housner_restitution(b.alpha_rad());
        for (double fraction : {0.95, 0.97}) {
            const RockingFit fit = calibrate_rocking(b, CalibratedParameter::h_n, fraction * housner, 1e-3);
            EXPECT_TRUE(fit.found) << "aspect " << aspect << ", " << fraction << " of Housner: reachable "
                                   << fit.reachable_min / housner << " to " << fit.reachable_max / housner;
            EXPECT_LT(fit.contact.h_n, 1.0);
            std::printf("aspect %g, target %.2f x Housner = %.4f: h_n = %.4f, r = %.4f, %d runs\n", aspect, fraction,
                        fraction * housner, fit.contact.h_n, fit.achieved_restitution, fit.dem_runs);
        }
    }
}

TEST(RockingCalibration, FitsKnAtAGivenDamping) {
    // The other way round: the damping held (h_n = 0.9, no tension), the stiffness found. A
    // softer contact loses more per impact, so 0.96 of Housner needs a kn well below 1e8.
    RockingBlock b = concrete_block(5.0, ContactTermination::no_tension);
    b.contact.h_n = 0.9;
    b.contact.ks_N_m = 0.5 * b.contact.kn_N_m;
    const double target = 0.96 * housner_restitution(b.alpha_rad());
    const RockingFit fit = calibrate_rocking(b, CalibratedParameter::kn, target, 1e-3);
    ASSERT_TRUE(fit.found) << "reachable " << fit.reachable_min << " to " << fit.reachable_max;
    EXPECT_LT(fit.contact.kn_N_m, 1.0e8);
    EXPECT_DOUBLE_EQ(fit.contact.ks_N_m, 0.5 * fit.contact.kn_N_m);
    EXPECT_DOUBLE_EQ(fit.contact.h_n, 0.9);
    std::printf("h_n = 0.9: kn = %.4g N/m gives r = %.4f (target %.4f), %d runs\n", fit.contact.kn_N_m,
                fit.achieved_restitution, target, fit.dem_runs);
}

TEST(RockingCalibration, UnreachableTargetSaysWhatIsReachable) {
    const RockingBlock b = concrete_block(5.0, ContactTermination::no_tension);
    const RockingFit fit = calibrate_rocking(b, CalibratedParameter::h_n, 0.3, 1e-3);
    EXPECT_FALSE(fit.found);
    EXPECT_GT(fit.reachable_min, 0.3);
    EXPECT_LE(fit.reachable_min, fit.reachable_max);
    EXPECT_EQ(fit.dem_runs, static_cast<int>(scanned_damping_ratios(ContactTermination::no_tension).size()));
}

}  // namespace
}  // namespace blockdem
