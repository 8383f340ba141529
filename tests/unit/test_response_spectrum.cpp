// Response spectrum against an independent check: the same oscillator integrated by classical
// Runge-Kutta with a step hundreds of times smaller than the record's, peak taken at every step.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "motion/records/ground_motion_record.hpp"
#include "motion/response_spectrum.hpp"
#include "records_test_support.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;

// u'' = -a_g(t) - 2 zeta w u' - w^2 u, a_g linear between samples and 0 after the record; run
// until one period after the end (the spectrum's definition). RK4, h <= min(dt / 20, T / 400).
double rk4_peak(const std::vector<double>& a, double dt, double period, double zeta) {
    const double w = 2.0 * pi / period;
    const int sub = static_cast<int>(std::ceil(std::max(20.0, 400.0 * dt / period)));
    const double h = dt / sub;
    auto ground = [&](double t) {
        const double x = t / dt;
        const auto i = static_cast<std::size_t>(std::floor(x));
        if (i + 1 >= a.size()) return 0.0;
        return a[i] + (a[i + 1] - a[i]) * (x - static_cast<double>(i));
    };
    auto f = [&](double t, double u, double v) { return -ground(t) - 2.0 * zeta * w * v - w * w * u; };
    double u = 0.0, v = 0.0, peak = 0.0;
    const auto steps = static_cast<long>(a.size() - 1 + std::ceil(period / dt)) * sub;
    for (long n = 0; n < steps; ++n) {
        const double t = static_cast<double>(n) * h;
        const double k1u = v, k1v = f(t, u, v);
        const double k2u = v + 0.5 * h * k1v, k2v = f(t + 0.5 * h, u + 0.5 * h * k1u, v + 0.5 * h * k1v);
        const double k3u = v + 0.5 * h * k2v, k3v = f(t + 0.5 * h, u + 0.5 * h * k2u, v + 0.5 * h * k2v);
        const double k4u = v + h * k3v, k4v = f(t + h, u + h * k3u, v + h * k3v);
        u += h / 6.0 * (k1u + 2 * k2u + 2 * k3u + k4u);
        v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
        peak = std::max(peak, std::abs(u));
    }
    return peak;
}

// A record-like test signal: two decaying sines, 8 s at 0.01 s.
std::vector<double> test_signal() {
    std::vector<double> a(801);
    for (std::size_t k = 0; k < a.size(); ++k) {
        const double t = 0.01 * static_cast<double>(k);
        a[k] = 3.0 * std::sin(2 * pi * 1.3 * t) * std::exp(-0.4 * t) + 1.5 * std::sin(2 * pi * 6.1 * t + 0.5) * std::exp(-0.7 * t);
    }
    return a;
}

const std::vector<double> check_periods{0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 4.0};

void expect_within_one_percent(const std::vector<double>& a, double dt, SpectrumMethod method) {
    SpectrumOptions o;
    o.periods_s = check_periods;
    o.method = method;
    const auto spectrum = response_spectrum(a, dt, o);
    double worst = 0.0;
    for (const auto& s : spectrum) {
        const double w = 2.0 * pi / s.period_s;
        const double reference = w * w * rk4_peak(a, dt, s.period_s, 0.05);
        const double error = std::abs(s.psa_m_s2 - reference) / reference;
        worst = std::max(worst, error);
        EXPECT_LT(error, 0.01) << "T = " << s.period_s << " s: " << s.psa_m_s2 << " vs " << reference;
    }
    ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst));
    std::printf("    worst PSa error vs RK4: %.2e\n", worst);
}

TEST(ResponseSpectrum, ExactMatchesFineRk4OnTestSignal) {
    expect_within_one_percent(test_signal(), 0.01, SpectrumMethod::exact_piecewise_linear);
}

TEST(ResponseSpectrum, NewmarkMatchesFineRk4OnTestSignal) {
    expect_within_one_percent(test_signal(), 0.01, SpectrumMethod::newmark_average_acceleration);
}

TEST(ResponseSpectrum, ExactMatchesFineRk4OnElCentro) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto r = read_ground_motion_record(testing::ground_motions_dir() / "peer-at2" / "IELC180.AT2");
    expect_within_one_percent(r.acceleration_m_s2, r.dt_s, SpectrumMethod::exact_piecewise_linear);
}

TEST(ResponseSpectrum, NewmarkMatchesFineRk4OnElCentro) {
    BLOCKDEM_REQUIRE_GROUND_MOTIONS();
    const auto r = read_ground_motion_record(testing::ground_motions_dir() / "peer-at2" / "IELC180.AT2");
    expect_within_one_percent(r.acceleration_m_s2, r.dt_s, SpectrumMethod::newmark_average_acceleration);
}

TEST(ResponseSpectrum, ZeroPeriodIsPgaAndLongPeriodTendsToZero) {
    const auto a = test_signal();
    SpectrumOptions o;
    o.periods_s = {0.0, 0.001, 100.0};
    const auto s = response_spectrum(a, 0.01, o);
    double pga = 0.0;
    for (double x : a) pga = std::max(pga, std::abs(x));
    EXPECT_DOUBLE_EQ(s[0].psa_m_s2, pga);
    EXPECT_NEAR(s[1].psa_m_s2, pga, 0.01 * pga);  // a very stiff oscillator follows the ground
    EXPECT_LT(s[2].psa_m_s2, 0.01 * pga);
}

TEST(ResponseSpectrum, ResonantSineMatchesSteadyStateAmplification) {
    // A long sine at the oscillator's period: steady-state amplification 1 / (2 zeta).
    const double period = 0.5, zeta = 0.05;
    std::vector<double> a(6001);
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = std::sin(2 * pi * 0.01 * static_cast<double>(k) / period);
    SpectrumOptions o;
    o.periods_s = {period};
    o.damping_ratio = zeta;
    const auto s = response_spectrum(a, 0.01, o);
    EXPECT_NEAR(s[0].psa_m_s2, 1.0 / (2.0 * zeta), 0.01 / (2.0 * zeta));
}

}  // namespace
}  // namespace blockdem
