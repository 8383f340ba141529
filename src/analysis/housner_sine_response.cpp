#include "analysis/housner_sine_response.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace blockdem {
namespace {

void require_positive(double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value))
        throw std::invalid_argument(fmt::format("Housner sine response: {} must be positive and finite, got {:g}", name, value));
}

// The state at time t, interpolated between the two history points around it (an impact
// inside the interval keeps theta continuous; theta' there is that of the nearer side).
RockingPoint state_at(const std::vector<RockingPoint>& history, std::size_t& j, double t) {
    while (j + 1 < history.size() && history[j + 1].time_s < t) ++j;
    if (j + 1 >= history.size()) return history.back();
    const RockingPoint& a = history[j];
    const RockingPoint& b = history[j + 1];
    const double f = b.time_s > a.time_s ? std::clamp((t - a.time_s) / (b.time_s - a.time_s), 0.0, 1.0) : 0.0;
    return {t, a.theta_rad + f * (b.theta_rad - a.theta_rad), f < 0.5 ? a.omega_rad_s : b.omega_rad_s};
}

}  // namespace

RockingSignal housner_rocking_signal(const RockingResult& result, const ComponentMotion& base, const RockingWindow& window) {
    RockingSignal s;
    s.window = window;
    if (!window.valid() || result.overturned || result.history.empty()) return s;
    const auto total = static_cast<std::size_t>(window.cycles) * static_cast<std::size_t>(window.samples_per_cycle);
    s.theta_rad.reserve(total);
    s.table_acceleration_m_s2.reserve(total);
    std::size_t j = 0;
    for (std::size_t k = 0; k < total; ++k) {
        const double t = window.start_s + static_cast<double>(k) * window.sample_interval_s();
        s.theta_rad.push_back(state_at(result.history, j, t).theta_rad);
        s.table_acceleration_m_s2.push_back(sample(base, t).acceleration_m_s2);
    }
    return s;
}

HousnerSineResponse housner_sine_response(const HousnerBlock& block, const HousnerSineCase& c) {
    require_positive(c.frequency_hz, "frequency [Hz]");
    require_positive(c.amplitude_m_s2, "amplitude [m/s^2]");
    require_positive(c.dt_s, "dt [s]");
    if (c.cycles < 2) throw std::invalid_argument(fmt::format("Housner sine response: cycles must be at least 2, got {}", c.cycles));
    SineMotion sine;
    sine.amplitude_m_s2 = c.amplitude_m_s2;
    sine.period_s = 1.0 / c.frequency_hz;
    sine.cycles = c.cycles;
    const ComponentMotion base = sine;
    const double duration_s = c.cycles * sine.period_s;
    const RockingResult r = housner_rocking(block, base, 0.0, 0.0, duration_s, c.dt_s);
    const RockingWindow window = rocking_window(sine, duration_s);

    HousnerSineResponse out;
    out.overturned = r.overturned;
    out.peak_abs_theta_rad = r.peak_abs_theta_rad;
    RockingSignal signal = housner_rocking_signal(r, base, window);
    signal.rocking_threshold_rad = 0.01 * block.alpha_rad();  // as the DEM's response monitor
    signal.overturned = r.overturned;
    signal.rocked = r.peak_abs_theta_rad >= signal.rocking_threshold_rad;
    out.classification = classify_rocking_mode(signal);
    if (r.overturned || !window.valid()) return out;
    std::size_t j = 0;
    for (int k = 0; k < window.cycles; ++k)
        out.poincare_section.push_back(state_at(r.history, j, window.start_s + k * window.period_s));
    for (double t : r.impact_times_s)
        if (t >= window.start_s && t < window.end_s()) ++out.impacts_in_window;
    return out;
}

}  // namespace blockdem
