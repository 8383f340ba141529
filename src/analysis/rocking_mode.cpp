#include "analysis/rocking_mode.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace blockdem {

std::string to_string(RockingMode mode) {
    switch (mode) {
        case RockingMode::none: return "none";
        case RockingMode::sliding: return "sliding";
        case RockingMode::in_phase: return "in_phase";
        case RockingMode::anti_phase: return "anti_phase";
        case RockingMode::subharmonic: return "subharmonic";
        case RockingMode::irregular: return "irregular";
        case RockingMode::rocking: return "rocking";
        case RockingMode::overturned: return "overturned";
    }
    return "none";
}

RockingWindow rocking_window(const SineMotion& sine, double duration_s) {
    RockingWindow w;
    w.period_s = sine.period_s;
    const double end_s = sine.cycles > 0.0 ? std::min(sine.start_s + sine.cycles * sine.period_s, duration_s) : duration_s;
    // Clamped as a double before the cast: a duration of 1e300 periods.
    const int available = static_cast<int>(std::clamp(std::floor((end_s - sine.start_s) / sine.period_s + 1e-9), -1.0, 1e6));
    if (available < 2) return w;
    // The start-up transient is left out; 6 | W lets the rocking period be 1, 2 or 3 periods.
    w.cycles = available >= 10 ? 6 * static_cast<int>(0.6 * available / 6.0) : available / 2;
    w.start_s = sine.start_s + (available - w.cycles) * sine.period_s;
    return w;
}

namespace {

constexpr double periodicity_limit = 0.3;  // relative RMS; a steady rocking repeats far better

// Rotations that change sign: one impact each (the block passes through upright).
std::size_t sign_changes(const std::vector<double>& theta) {
    std::size_t n = 0;
    for (std::size_t k = 1; k < theta.size(); ++k)
        if ((theta[k - 1] < 0.0) != (theta[k] < 0.0)) ++n;
    return n;
}

double mean_of(const std::vector<double>& x) {
    double s = 0.0;
    for (double v : x) s += v;
    return x.empty() ? 0.0 : s / static_cast<double>(x.size());
}

// Fourier component of x - mean at the frequency of one cycle every `period_samples` samples.
std::complex<double> component(const std::vector<double>& x, double mean, int period_samples) {
    std::complex<double> sum{0.0, 0.0};
    const double w = 2.0 * std::numbers::pi / period_samples;
    for (std::size_t k = 0; k < x.size(); ++k) sum += (x[k] - mean) * std::polar(1.0, -w * static_cast<double>(k));
    return sum * (2.0 / static_cast<double>(x.size()));
}

// RMS of x(t) - x(t - lag) over the second half of the window (a slowly dying start-up
// asymmetry should not count), relative to the RMS of x - mean there.
double periodicity_error(const std::vector<double>& x, double mean, std::size_t lag) {
    double diff = 0.0, spread = 0.0;
    const std::size_t first = std::max(lag, x.size() / 2);
    for (std::size_t k = first; k < x.size(); ++k) {
        diff += (x[k] - x[k - lag]) * (x[k] - x[k - lag]);
        spread += (x[k] - mean) * (x[k] - mean);
    }
    const double diff_rms = std::sqrt(diff / static_cast<double>(x.size() - first));
    const double spread_rms = std::sqrt(spread / static_cast<double>(x.size() - first));
    return spread_rms > 0.0 ? diff_rms / spread_rms : 0.0;
}

double wrap_angle(double a) {
    a = std::remainder(a, 2.0 * std::numbers::pi);
    return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

RockingClassification without_rocking(const RockingSignal& s) {
    RockingClassification c;
    c.mode = s.slid ? RockingMode::sliding : RockingMode::none;
    return c;
}

}  // namespace

RockingClassification classify_rocking_mode(const RockingSignal& s) {
    RockingClassification c;
    if (s.overturned) {
        c.mode = RockingMode::overturned;
        return c;
    }
    const RockingWindow& w = s.window;
    const std::size_t expected = static_cast<std::size_t>(w.cycles) * static_cast<std::size_t>(w.samples_per_cycle);
    if (!w.valid() || s.theta_rad.size() != expected) {
        if (!s.rocked) return without_rocking(s);
        c.mode = RockingMode::rocking;
        return c;
    }
    double peak = 0.0;
    for (double v : s.theta_rad) peak = std::max(peak, std::abs(v));
    if (peak < s.rocking_threshold_rad) return without_rocking(s);

    const double mean = mean_of(s.theta_rad);
    c.impacts_per_period = static_cast<double>(sign_changes(s.theta_rad)) / w.cycles;
    // The period: the smallest n whose Poincare sections repeat after n points. A period-1
    // orbit also repeats after 2 and 3 periods, so the smallest one is the orbit's period.
    int smallest_error_n = 0;
    for (int n = 1; n <= max_period_ratio; ++n) {
        if (2 * n > w.cycles) continue;  // two whole orbits in the window
        const double e = periodicity_error(s.theta_rad, mean, static_cast<std::size_t>(n * w.samples_per_cycle));
        c.repeat_error[static_cast<std::size_t>(n - 1)] = e;
        if (c.period_ratio == 0 && e <= periodicity_limit) c.period_ratio = n;
        if (smallest_error_n == 0 || e < c.repeat_error[static_cast<std::size_t>(smallest_error_n - 1)]) smallest_error_n = n;
    }
    if (smallest_error_n == 0) {
        c.mode = RockingMode::rocking;  // window too short to tell
        return c;
    }
    if (c.period_ratio == 0) {
        // No period up to 3 repeats: report the closest, for the record.
        c.mode = RockingMode::irregular;
        c.periodicity_error = c.repeat_error[static_cast<std::size_t>(smallest_error_n - 1)];
        return c;
    }
    c.periodicity_error = c.repeat_error[static_cast<std::size_t>(c.period_ratio - 1)];
    if (c.period_ratio >= 2) {
        c.mode = RockingMode::subharmonic;
        return c;
    }
    const std::complex<double> theta1 = component(s.theta_rad, mean, w.samples_per_cycle);
    const std::complex<double> table1 =
        component(s.table_acceleration_m_s2, mean_of(s.table_acceleration_m_s2), w.samples_per_cycle);
    c.phase_lag_rad = wrap_angle(std::arg(table1) - std::arg(theta1));
    c.mode = std::abs(c.phase_lag_rad) < 0.5 * std::numbers::pi ? RockingMode::in_phase : RockingMode::anti_phase;
    return c;
}

RockingModeObserver::RockingModeObserver(const World& w, RockingWindow window)
    : window_(window), theta_rad_(w.bodies.size()) {
    const std::size_t n = static_cast<std::size_t>(window_.cycles) * static_cast<std::size_t>(window_.samples_per_cycle);
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.bodies.kind[i] != BodyKind::dynamic) continue;
        theta_rad_[i].reserve(n);
    }
    table_acceleration_m_s2_.reserve(n);
}

void RockingModeObserver::observe(const World& w) {
    if (!window_.valid()) return;
    const std::size_t total = static_cast<std::size_t>(window_.cycles) * static_cast<std::size_t>(window_.samples_per_cycle);
    // The step nearest to each sample time (the step is far shorter than the sample interval).
    while (next_sample_ < total &&
           w.time_s + 0.5 * w.dt_s >= window_.start_s + static_cast<double>(next_sample_) * window_.sample_interval_s()) {
        for (std::size_t i = 0; i < w.bodies.size(); ++i)
            if (w.bodies.kind[i] == BodyKind::dynamic) theta_rad_[i].push_back(w.bodies.rotation_rad[i]);
        table_acceleration_m_s2_.push_back(sample(w.table_motion.horizontal, w.time_s).acceleration_m_s2);
        ++next_sample_;
    }
}

RockingSignal RockingModeObserver::signal_of(std::size_t body) const {
    RockingSignal s;
    s.window = window_;
    s.theta_rad = theta_rad_[body];
    s.table_acceleration_m_s2 = table_acceleration_m_s2_;
    return s;
}

}  // namespace blockdem
