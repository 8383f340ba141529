#include "motion/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "motion/linear_oscillator.hpp"

namespace blockdem {
namespace {

constexpr double steps_per_period = 50.0;  // peak sampling error below 0.2 % (1 - cos(pi / 50))

// Newmark average acceleration on u'' + c u' + k u = f (unit mass), incremental form.
class NewmarkStep {
public:
    NewmarkStep(double omega, double zeta, double h)
        : c_(2.0 * zeta * omega), k_(omega * omega), h_(h), k_eff_(k_ + 2.0 * c_ / h + 4.0 / (h * h)) {}
    // state (u, v), acceleration acc at the start; force f0 -> f1. Returns the new acceleration via acc.
    OscillatorState advance(OscillatorState s, double& acc, double f1) const {
        const double rhs = f1 + (4.0 / (h_ * h_)) * s.x + (4.0 / h_) * s.v + acc + c_ * ((2.0 / h_) * s.x + s.v);
        const double u1 = rhs / k_eff_;
        const double v1 = 2.0 * (u1 - s.x) / h_ - s.v;
        acc = f1 - c_ * v1 - k_ * u1;
        return {u1, v1};
    }

private:
    double c_, k_, h_, k_eff_;
};

// Ground acceleration at sub-step j of n within step i (linear between samples).
double ground(std::span<const double> a, std::size_t i, std::size_t j, std::size_t n) {
    if (i + 1 >= a.size()) return 0.0;  // free vibration after the record
    return a[i] + (a[i + 1] - a[i]) * static_cast<double>(j) / static_cast<double>(n);
}

template <class Advance>
double peak_response(std::span<const double> a, double dt, double period, Advance&& advance) {
    const auto sub = static_cast<std::size_t>(std::ceil(dt * steps_per_period / period));
    const std::size_t free_steps = static_cast<std::size_t>(std::ceil(period / dt));  // one period after the end
    OscillatorState s;
    double peak = 0.0;
    for (std::size_t i = 0; i + 1 < a.size() + free_steps; ++i)
        for (std::size_t j = 0; j < sub; ++j) {
            s = advance(s, -ground(a, i, j, sub), -ground(a, i, j + 1, sub));
            peak = std::max(peak, std::abs(s.x));
        }
    return peak;
}

}  // namespace

SpectrumMethod parse_spectrum_method(std::string_view name) {
    if (name == "exact") return SpectrumMethod::exact_piecewise_linear;
    if (name == "newmark") return SpectrumMethod::newmark_average_acceleration;
    throw std::invalid_argument(fmt::format("unknown spectrum method '{}'; use exact or newmark", name));
}

double checked_spectrum_period(double period_s) {
    if (period_s == 0.0 || (period_s >= min_spectrum_period_s && period_s <= max_spectrum_period_s)) return period_s;
    throw std::invalid_argument(fmt::format("period {:g} s is outside {:g} s to {:g} s (0 gives the PGA)", period_s,
                                            min_spectrum_period_s, max_spectrum_period_s));
}

std::vector<double> log_spaced_periods(double min_s, double max_s, std::size_t count) {
    if (!(min_s > 0.0) || !(max_s > min_s) || count < 2) throw std::invalid_argument("periods need 0 < min < max and count >= 2");
    std::vector<double> out(count);
    for (std::size_t i = 0; i < count; ++i)
        out[i] = min_s * std::pow(max_s / min_s, static_cast<double>(i) / static_cast<double>(count - 1));
    return out;
}

std::vector<double> default_spectrum_periods() { return log_spaced_periods(0.01, 10.0, 100); }

double peak_oscillator_displacement(std::span<const double> a, double dt, double period, double zeta, SpectrumMethod method) {
    if (a.size() < 2 || !(dt > 0.0) || !std::isfinite(dt) || !(zeta >= 0.0) || !(zeta < 1e3))
        throw std::invalid_argument("an oscillator needs 2 samples, a finite dt > 0 and damping >= 0");
    if (!(period > 0.0)) throw std::invalid_argument(fmt::format("an oscillator needs a period > 0, not {:g} s", period));
    checked_spectrum_period(period);
    // Work is (samples + one period) x sub-steps: bounded by the period range and the record.
    if (dt / period > 1e6 || period / dt > 1e9)
        throw std::invalid_argument(fmt::format("a period of {:g} s and a sample interval of {:g} s are too far apart", period, dt));
    const double omega = 2.0 * std::numbers::pi / period;
    const double h = dt / std::ceil(dt * steps_per_period / period);
    if (method == SpectrumMethod::exact_piecewise_linear) {
        const OscillatorStep step(omega, zeta, h);
        return peak_response(a, dt, period, [&](OscillatorState s, double f0, double f1) { return step.advance(s, f0, f1); });
    }
    const NewmarkStep step(omega, zeta, h);
    double acc = -a[0];  // u'' at rest under the first ground acceleration
    return peak_response(a, dt, period, [&](OscillatorState s, double, double f1) { return step.advance(s, acc, f1); });
}

std::vector<SpectrumOrdinate> response_spectrum(std::span<const double> a, double dt, const SpectrumOptions& options) {
    const std::vector<double> periods = options.periods_s.empty() ? default_spectrum_periods() : options.periods_s;
    for (double period : periods) checked_spectrum_period(period);
    std::vector<SpectrumOrdinate> out;
    for (double period : periods) {
        if (period <= 0.0) {  // a rigid oscillator moves with the ground: PSa = PGA
            double pga = 0.0;
            for (double x : a) pga = std::max(pga, std::abs(x));
            out.push_back({0.0, 0.0, 0.0, pga});
            continue;
        }
        const double omega = 2.0 * std::numbers::pi / period;
        const double sd = peak_oscillator_displacement(a, dt, period, options.damping_ratio, options.method);
        out.push_back({period, sd, omega * sd, omega * omega * sd});
    }
    return out;
}

}  // namespace blockdem
