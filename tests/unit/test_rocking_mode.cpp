// The rocking-mode rule (analysis/rocking_mode.hpp) on constructed signals, where the answer is
// known by construction, and on two real DEM runs of a slender block on a sine table.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "analysis/rocking_mode.hpp"
#include "sweep/case_runner.hpp"

namespace blockdem {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double period = 0.5;     // [s]
constexpr double threshold = 1e-3; // [rad]

// theta(t) and a(t) = sin(2 pi t / T) sampled over the window of a 20-cycle sine.
RockingSignal constructed(const std::function<double(double)>& theta) {
    SineMotion sine;
    sine.amplitude_m_s2 = 1.0;
    sine.period_s = period;
    RockingSignal s;
    s.window = rocking_window(sine, 20 * period);
    for (int k = 0; k < s.window.cycles * s.window.samples_per_cycle; ++k) {
        const double t = s.window.start_s + k * s.window.sample_interval_s();
        s.theta_rad.push_back(theta(t));
        s.table_acceleration_m_s2.push_back(sample(SineMotion(sine), t).acceleration_m_s2);
    }
    s.rocking_threshold_rad = threshold;
    s.rocked = true;
    return s;
}

double w() { return 2.0 * pi / period; }

TEST(RockingMode, WindowIsTheLastWholeMultipleOfSixPeriods) {
    SineMotion sine;
    sine.period_s = 0.5;
    const RockingWindow a = rocking_window(sine, 10.0);  // 20 periods: 12 of them, from t = 4 s
    EXPECT_EQ(a.cycles, 12);
    EXPECT_DOUBLE_EQ(a.start_s, 4.0);
    sine.cycles = 8;                                     // the sine stops after 4 s: 4 periods
    const RockingWindow b = rocking_window(sine, 10.0);
    EXPECT_EQ(b.cycles, 4);
    EXPECT_DOUBLE_EQ(b.start_s, 2.0);
    sine.cycles = 1;
    EXPECT_FALSE(rocking_window(sine, 10.0).valid());
}

TEST(RockingMode, InPhaseAndAntiPhaseFromThePhaseLag) {
    for (double lag_deg : {0.0, 30.0, 80.0, -60.0}) {
        const double lag = lag_deg * pi / 180.0;
        const auto c = classify_rocking_mode(constructed([&](double t) { return 0.05 * std::sin(w() * t - lag); }));
        EXPECT_EQ(c.mode, RockingMode::in_phase) << lag_deg;
        EXPECT_NEAR(c.phase_lag_rad, lag, 1e-6) << lag_deg;
        EXPECT_EQ(c.period_ratio, 1);
    }
    for (double lag_deg : {100.0, 180.0, -120.0}) {
        const double lag = lag_deg * pi / 180.0;
        const auto c = classify_rocking_mode(constructed([&](double t) { return 0.05 * std::sin(w() * t - lag); }));
        EXPECT_EQ(c.mode, RockingMode::anti_phase) << lag_deg;
    }
}

TEST(RockingMode, RockingShapedSignalKeepsItsPhase) {
    // Rocking is not a sine: arcs that meet at impacts. |sin|^0.7 with the sine's sign has sharp
    // impacts and flat tops, and still the phase of its fundamental.
    auto arcs = [](double x) { return 0.1 * std::copysign(std::pow(std::abs(std::sin(x)), 0.7), std::sin(x)); };
    EXPECT_EQ(classify_rocking_mode(constructed([&](double t) { return arcs(w() * t); })).mode, RockingMode::in_phase);
    EXPECT_EQ(classify_rocking_mode(constructed([&](double t) { return -arcs(w() * t); })).mode, RockingMode::anti_phase);
}

TEST(RockingMode, SubharmonicFromTheRockingPeriod) {
    for (int n : {2, 3}) {
        const auto c = classify_rocking_mode(constructed([&](double t) { return 0.08 * std::sin(w() * t / n + 0.3); }));
        EXPECT_EQ(c.mode, RockingMode::subharmonic) << n;
        EXPECT_EQ(c.period_ratio, n);
    }
    // A subharmonic response with a forced component at the table frequency: n = 3 dominates.
    const auto c = classify_rocking_mode(
        constructed([&](double t) { return 0.08 * std::sin(w() * t / 3) + 0.02 * std::sin(w() * t); }));
    EXPECT_EQ(c.mode, RockingMode::subharmonic);
    EXPECT_EQ(c.period_ratio, 3);
}

TEST(RockingMode, OneSidedRockingIsClassifiedByItsFundamental) {
    // Rocking on one corner only (theta never changes sign): the mean is removed first.
    const auto c = classify_rocking_mode(constructed([&](double t) { return 0.03 * (1.0 + std::sin(w() * t)); }));
    EXPECT_EQ(c.mode, RockingMode::in_phase);
}

TEST(RockingMode, NonPeriodicRockingIsIrregular) {
    // Two incommensurate frequencies: no period of 1, 2 or 3 table periods repeats it.
    const auto c = classify_rocking_mode(
        constructed([&](double t) { return 0.05 * std::sin(w() * t * 0.618) + 0.05 * std::sin(w() * t * 0.277); }));
    EXPECT_EQ(c.mode, RockingMode::irregular);
    EXPECT_GT(c.periodicity_error, 0.3);
}

TEST(RockingMode, RestSlidingAndOverturnedFromTheFlags) {
    RockingSignal quiet = constructed([](double t) { return 0.1 * threshold * std::sin(w() * t); });
    EXPECT_EQ(classify_rocking_mode(quiet).mode, RockingMode::none);
    quiet.slid = true;
    EXPECT_EQ(classify_rocking_mode(quiet).mode, RockingMode::sliding);
    quiet.overturned = true;
    EXPECT_EQ(classify_rocking_mode(quiet).mode, RockingMode::overturned);
    // Not a sine table: no window, and rocking has no sub-mode.
    RockingSignal pulse;
    pulse.rocked = true;
    EXPECT_EQ(classify_rocking_mode(pulse).mode, RockingMode::rocking);
    EXPECT_EQ(to_string(RockingMode::anti_phase), "anti_phase");
}

// Real runs: a slender block (b = 0.1 m, h = 0.4 m, g tan(alpha) = 2.45 m/s^2) on the study's
// sine table. Slightly above the static threshold at a long period it rocks in phase with
// small uplift; at 3 Hz and 3.5 m/s^2 it settles into steady anti-phase rocking (phase lag
// near 180 deg), the mode the paper says is stable well above g b/h.
sweep::BodyOutcome run_sine(double period_s, double amplitude_m_s2, int cycles) {
    const auto scenario = sweep::load_sweep_scenario(BLOCKDEM_SOURCE_DIR "/studies/scenarios/sine_block.toml");
    sweep::SweepCase c;
    c.assignments = {{"table_motion.horizontal.period", std::to_string(period_s)},
                     {"table_motion.horizontal.amplitude", std::to_string(amplitude_m_s2)},
                     {"table_motion.horizontal.cycles", std::to_string(cycles)},
                     {"simulation.duration", std::to_string(cycles * period_s)}};
    const sweep::CaseResult r = sweep::run_case(scenario, sweep::SweepPlan{}, c, sweep::CaseOptions{}, nullptr);
    EXPECT_EQ(r.status, "completed") << r.error;
    return r.bodies.at(0).value();
}

TEST(RockingModeRuns, InPhaseJustAboveTheStaticThresholdAtLowFrequency) {
    const sweep::BodyOutcome o = run_sine(2.0, 2.55, 12);
    EXPECT_EQ(o.mode, "in_phase") << "phase lag " << o.phase_lag_deg << " deg";
    EXPECT_LT(std::abs(o.phase_lag_deg), 60.0);
}

TEST(RockingModeRuns, AntiPhaseAtHigherFrequency) {
    const sweep::BodyOutcome o = run_sine(1.0 / 3.0, 3.5, 24);
    EXPECT_EQ(o.mode, "anti_phase") << "phase lag " << o.phase_lag_deg << " deg";
    EXPECT_GT(std::abs(o.phase_lag_deg), 150.0);
    EXPECT_LT(o.peak_sliding_m, 1e-3);  // mu = 2 > b/h: it rocks, slipping less than 1 mm at impacts
}

}  // namespace
}  // namespace blockdem
