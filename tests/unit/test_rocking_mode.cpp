// The rocking-mode rule (analysis/rocking_mode.hpp) on constructed signals, where the answer is
// known by construction, and on two real DEM runs of a slender block on a sine table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "analysis/housner_sine_response.hpp"
#include "analysis/rocking_mode.hpp"
#include "io/scenario.hpp"
#include "sweep/case_runner.hpp"
#include "world/simulation.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;
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

TEST(RockingMode, TheOrbitPeriodIsTheSmallestThatRepeatsEvenWhenTheTableHarmonicDominates) {
    // Subharmonic orbits often carry more of the table frequency than of their own (a forced
    // wiggle on a slow swing): the period is the smallest n after which theta repeats, not the
    // largest Fourier component.
    for (int n : {2, 3}) {
        const auto c = classify_rocking_mode(
            constructed([&](double t) { return 0.02 * std::sin(w() * t / n + 0.5) + 0.06 * std::sin(w() * t); }));
        EXPECT_EQ(c.mode, RockingMode::subharmonic) << n;
        EXPECT_EQ(c.period_ratio, n);
        EXPECT_GT(c.repeat_error[0], 0.3) << n;
        EXPECT_LT(c.repeat_error[static_cast<std::size_t>(n - 1)], 1e-9) << n;
    }
    // A period-1 orbit repeats after 1, 2 and 3 periods: it is period 1.
    const auto one = classify_rocking_mode(constructed([&](double t) { return 0.05 * std::sin(w() * t + 2.0); }));
    EXPECT_EQ(one.period_ratio, 1);
    for (double e : one.repeat_error) EXPECT_LT(e, 1e-9);
    EXPECT_NEAR(one.impacts_per_period, 2.0, 0.1);  // two sign changes of theta per table period
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
    EXPECT_EQ(c.period_ratio, 0);
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
    // Full precision: a 1/6 s period written with 6 digits would be another frequency.
    auto text = [](double v) { return fmt::format("{:.17g}", v); };
    c.assignments = {{"table_motion.horizontal.period", text(period_s)},
                     {"table_motion.horizontal.amplitude", text(amplitude_m_s2)},
                     {"table_motion.horizontal.cycles", std::to_string(cycles)},
                     {"simulation.duration", text(cycles * period_s)}};
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

// The subharmonic point (docs/rocking_modes.md): the same block, Housner's r = 1 - 1.5 sin^2
// alpha = 0.912 (the DEM's e = 0.2 contact loses the same share per impact, validation
// test_rocking), a sine of 6 Hz and 1.0 g (four times g tan alpha) for 120 periods from rest.
// Housner's solver settles into a period-3 orbit: the block rocks once to each side every three
// table periods (2 impacts per 3 periods), the symmetric (1,3) subharmonic of Hogan (1989); the
// DEM at the same point settles into the same orbit.
constexpr double subharmonic_frequency_hz = 6.0;
constexpr double subharmonic_amplitude_m_s2 = 9.81;
constexpr int subharmonic_cycles = 120;

HousnerBlock sine_block_as_housner() {
    HousnerBlock b;
    b.half_width_m = 0.1;
    b.half_height_m = 0.4;
    b.gravity_m_s2 = 9.81;
    return b;
}

TEST(HousnerSineResponse, FindsTheSubharmonicPeriodThreeOrbit) {
    HousnerSineCase c;
    c.frequency_hz = subharmonic_frequency_hz;
    c.amplitude_m_s2 = subharmonic_amplitude_m_s2;
    c.cycles = subharmonic_cycles;
    const HousnerSineResponse r = housner_sine_response(sine_block_as_housner(), c);
    EXPECT_FALSE(r.overturned);
    EXPECT_EQ(r.classification.mode, RockingMode::subharmonic);
    EXPECT_EQ(r.classification.period_ratio, 3);
    EXPECT_LT(r.classification.repeat_error[2], 0.05);  // steady: repeats after 3 periods
    EXPECT_GT(r.classification.repeat_error[0], 1.0);   // and not after 1 or 2
    EXPECT_GT(r.classification.repeat_error[1], 1.0);
    // The Poincare section (theta at each period's start) cycles through three points.
    const auto& p = r.poincare_section;
    ASSERT_EQ(p.size(), 72u);
    for (std::size_t k = p.size() - 9; k < p.size(); ++k) {
        EXPECT_NEAR(p[k].theta_rad, p[k - 3].theta_rad, 2e-4) << k;
        EXPECT_GT(std::abs(p[k].theta_rad - p[k - 1].theta_rad), 5e-3) << k;
    }
    EXPECT_EQ(r.impacts_in_window, 48);  // 2 impacts every 3 periods over 72 periods
}

TEST(HousnerSineResponse, RejectsANonPositiveCase) {
    HousnerSineCase c;
    c.amplitude_m_s2 = 0.0;
    EXPECT_THROW(housner_sine_response(sine_block_as_housner(), c), std::invalid_argument);
    c.amplitude_m_s2 = 5.0;
    c.frequency_hz = -1.0;
    EXPECT_THROW(housner_sine_response(sine_block_as_housner(), c), std::invalid_argument);
    c.frequency_hz = 2.0;
    c.cycles = 1;
    EXPECT_THROW(housner_sine_response(sine_block_as_housner(), c), std::invalid_argument);
}

TEST(RockingModeRuns, SubharmonicPeriodThreeAsHousnerAtSixHertzAndOneG) {
    const sweep::BodyOutcome o = run_sine(1.0 / subharmonic_frequency_hz, subharmonic_amplitude_m_s2, subharmonic_cycles);
    EXPECT_EQ(o.mode, "subharmonic");
    EXPECT_EQ(o.rocking_period_ratio, 3);
    EXPECT_FALSE(o.failed);
}

// theta at the start of each of the last three window periods: one turn of a period-3 orbit,
// sorted (where the turn starts depends on the start-up).
std::vector<double> last_turn_sorted(std::vector<double> section) {
    std::vector<double> turn(section.end() - 3, section.end());
    std::sort(turn.begin(), turn.end());
    return turn;
}

TEST(RockingModeRuns, SubharmonicOrbitOfTheDemIsHousnersOrbit) {
    // Not only the same label: the DEM's Poincare section lies on Housner's three points.
    const double period_s = 1.0 / subharmonic_frequency_hz;
    auto text = [](double v) { return fmt::format("{:.17g}", v); };
    LoadedScenario s = load_scenario(BLOCKDEM_SOURCE_DIR "/studies/scenarios/sine_block.toml",
                                     {"table_motion.horizontal.period=" + text(period_s),
                                      "table_motion.horizontal.amplitude=" + text(subharmonic_amplitude_m_s2),
                                      "table_motion.horizontal.cycles=" + std::to_string(subharmonic_cycles),
                                      "simulation.duration=" + text(subharmonic_cycles * period_s)});
    World& w = s.world;
    const RockingWindow window = rocking_window(std::get<SineMotion>(w.table_motion.horizontal), w.settings.duration_s);
    RockingModeObserver observer(w, window);
    RunOptions run;
    run.on_step = [&](const World& world) { observer.observe(world); };
    run_simulation(w, run);
    const std::size_t block = 1;
    ASSERT_EQ(w.bodies.name[block], "block");
    const RockingSignal dem = observer.signal_of(block);
    std::vector<double> dem_section;
    for (std::size_t k = 0; k < dem.theta_rad.size(); k += static_cast<std::size_t>(window.samples_per_cycle))
        dem_section.push_back(dem.theta_rad[k]);

    HousnerSineCase c;
    c.frequency_hz = subharmonic_frequency_hz;
    c.amplitude_m_s2 = subharmonic_amplitude_m_s2;
    c.cycles = subharmonic_cycles;
    const HousnerSineResponse housner = housner_sine_response(sine_block_as_housner(), c);
    std::vector<double> housner_section;
    for (const RockingPoint& p : housner.poincare_section) housner_section.push_back(p.theta_rad);

    ASSERT_EQ(dem_section.size(), housner_section.size());
    const auto a = last_turn_sorted(dem_section), b = last_turn_sorted(housner_section);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(a[k], b[k], 1e-3) << "point " << k << " of the turn";  // about 3% of the swing
}

}  // namespace
}  // namespace blockdem
