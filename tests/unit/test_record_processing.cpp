// Record processing: window, taper, padding, scaling, baseline correction and resampling.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "motion/intensity_measures.hpp"
#include "motion/record_processing.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/table_motion.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;

std::vector<double> ramp(std::size_t n) {
    std::vector<double> a(n);
    for (std::size_t k = 0; k < n; ++k) a[k] = static_cast<double>(k);
    return a;
}

TEST(RecordWindow, IncludesBothEndsOnSamples) {
    const auto w = time_window(ramp(100), 0.01, 0.25, 0.5);
    ASSERT_EQ(w.size(), 51u);
    EXPECT_EQ(w.front(), 25.0);
    EXPECT_EQ(w.back(), 75.0);
    EXPECT_EQ(time_window(ramp(100), 0.01, 0.0, 0.0).size(), 100u);
    EXPECT_THROW(time_window(ramp(100), 0.01, 2.0, 0.0), std::invalid_argument);
}

TEST(RecordTaper, EndsAtZeroAndKeepsTheMiddle) {
    std::vector<double> a(101, 1.0);
    apply_cosine_taper(a, 0.01, 0.2);
    EXPECT_EQ(a.front(), 0.0);
    EXPECT_EQ(a.back(), 0.0);
    EXPECT_NEAR(a[10], 0.5, 1e-12);
    EXPECT_EQ(a[50], 1.0);
}

TEST(RecordPad, AppendsWholeSamplesOfZero) {
    std::vector<double> a(10, 1.0);
    pad_with_zeros(a, 0.01, 0.5);
    EXPECT_EQ(a.size(), 60u);
    EXPECT_EQ(a.back(), 0.0);
}

TEST(RecordScale, TargetPga) {
    const std::vector<double> a{0.1, -0.4, 0.2};
    EXPECT_DOUBLE_EQ(scale_factor_for_pga(a, 2.0), 5.0);
    RecordProcessing p;
    p.target_pga_m_s2 = 2.0;
    const auto out = process_record(a, 0.01, p);
    EXPECT_DOUBLE_EQ(out[1], -2.0);
}

// A sine plus a constant offset: the offset makes v drift linearly; "linear" removes it exactly.
TEST(RecordBaseline, LinearRemovesAConstantOffset) {
    std::vector<double> a(1001);
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = std::sin(2 * pi * 0.01 * k) + 0.05;  // 1 Hz over 10 s
    const auto before = intensity_measures(a, 0.01);
    const auto after = intensity_measures(correct_baseline(a, 0.01, {BaselineMethod::linear, 1}), 0.01);
    EXPECT_NEAR(before.final_velocity_m_s, 0.5, 1e-3);
    EXPECT_LT(std::abs(after.final_velocity_m_s), 1e-3);
}

TEST(RecordBaseline, PolynomialAndDisplacementFitsReduceDrift) {
    std::vector<double> a(2001);
    for (std::size_t k = 0; k < a.size(); ++k) {
        const double t = 0.01 * k;
        a[k] = 2.0 * std::sin(2 * pi * 1.7 * t) * std::exp(-0.3 * t) + 0.02 + 0.004 * t;  // offset and trend
    }
    const auto raw = intensity_measures(a, 0.01);
    for (auto method : {BaselineMethod::mean, BaselineMethod::polynomial, BaselineMethod::displacement_polynomial}) {
        const auto c = intensity_measures(correct_baseline(a, 0.01, {method, 3}), 0.01);
        EXPECT_LT(std::abs(c.final_displacement_m), 0.2 * std::abs(raw.final_displacement_m)) << baseline_method_name(method);
    }
    const auto poly = intensity_measures(correct_baseline(a, 0.01, {BaselineMethod::polynomial, 3}), 0.01);
    EXPECT_LT(std::abs(poly.final_velocity_m_s), 1e-12);
    EXPECT_LT(std::abs(poly.final_displacement_m), 1e-12);
    const auto disp = intensity_measures(correct_baseline(a, 0.01, {BaselineMethod::displacement_polynomial, 4}), 0.01);
    EXPECT_LT(std::abs(disp.final_velocity_m_s), 1e-12);
    EXPECT_LT(std::abs(disp.final_displacement_m), 1e-12);
    EXPECT_THROW(correct_baseline(a, 0.01, {BaselineMethod::polynomial, 9}), std::invalid_argument);
    EXPECT_THROW(correct_baseline(a, 0.01, {BaselineMethod::displacement_polynomial, 2}), std::invalid_argument);
}

TEST(RecordBaseline, ElCentroPeknoldDrift) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    RecordReadOptions o;
    o.units = "g";
    o.dt_s = 0.02;
    const auto r = read_ground_motion_record(testing::ground_motions_dir() / "plain-text" / "elCentro.dat", o);
    const auto raw = intensity_measures(r.acceleration_m_s2, r.dt_s);
    const auto c = intensity_measures(correct_baseline(r.acceleration_m_s2, r.dt_s, {BaselineMethod::polynomial, 3}), r.dt_s);
    std::printf("    El Centro (Peknold): v_end %.4f -> %.4f m/s, u_end %.4f -> %.4f m\n", raw.final_velocity_m_s,
                c.final_velocity_m_s, raw.final_displacement_m, c.final_displacement_m);
    EXPECT_LT(std::abs(c.final_displacement_m), 1e-9);
    EXPECT_LT(std::abs(c.final_velocity_m_s), 1e-9);
    EXPECT_LT(std::abs(c.pga_m_s2 - raw.pga_m_s2), 0.01 * raw.pga_m_s2);  // the correction is small
}

TEST(RecordResample, KeepsEverySampleAndTheKinematics) {
    const std::vector<double> a{0.0, 1.0, -2.0, 0.5, 3.0, 0.0};  // dt = 0.01
    const auto r = resample_keeping_samples(a, 0.01, 0.003);
    for (std::size_t k = 0; k < a.size(); ++k) {
        const auto at = std::find_if(r.time_s.begin(), r.time_s.end(), [&](double t) { return std::abs(t - 0.01 * k) < 1e-12; });
        ASSERT_NE(at, r.time_s.end()) << k;
        EXPECT_EQ(r.acceleration_m_s2[static_cast<std::size_t>(at - r.time_s.begin())], a[k]);
    }
    // The same function: the end velocity and displacement of the table are unchanged.
    std::vector<double> t(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) t[k] = 0.01 * k;
    const auto original = make_acceleration_series(t, a);
    const auto resampled = make_acceleration_series(r.time_s, r.acceleration_m_s2);
    EXPECT_NEAR(original.velocity_m_s.back(), resampled.velocity_m_s.back(), 1e-15);
    EXPECT_NEAR(original.displacement_m.back(), resampled.displacement_m.back(), 1e-15);
    // dt a multiple of the step: a uniform grid.
    EXPECT_EQ(resample_keeping_samples(a, 0.01, 0.0025).time_s.size(), 21u);
}

TEST(RecordResample, StepDividingTheRecordStep) {
    EXPECT_DOUBLE_EQ(step_dividing(0.01, 1e-4), 1e-4);
    EXPECT_NEAR(step_dividing(0.01, 3e-4), 0.01 / 34, 1e-18);
    EXPECT_DOUBLE_EQ(step_dividing(0.005, 0.01), 0.005);
}

}  // namespace
}  // namespace blockdem
