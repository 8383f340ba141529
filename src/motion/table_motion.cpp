#include "motion/table_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace blockdem {
namespace {

using std::numbers::pi;

// Sine from rest at tau = 0: a = A sin(w tau + phi); v, u are its exact integrals.
MotionSample sine_from_rest(double amplitude, double period, double phase, double tau) {
    const double w = 2.0 * pi / period;
    MotionSample s;
    s.acceleration_m_s2 = amplitude * std::sin(w * tau + phase);
    s.velocity_m_s = amplitude / w * (std::cos(phase) - std::cos(w * tau + phase));
    s.displacement_m = amplitude / w * std::cos(phase) * tau -
                       amplitude / (w * w) * (std::sin(w * tau + phase) - std::sin(phase));
    return s;
}

// A motion that ends at tau_end keeps its final velocity afterwards (no acceleration).
MotionSample coast_after(MotionSample end, double dt_after) {
    return {end.displacement_m + end.velocity_m_s * dt_after, end.velocity_m_s, 0.0};
}

MotionSample sample_sine(const SineMotion& m, double t) {
    const double tau = t - m.start_s;
    if (tau < 0.0) return {};
    const double tau_end = m.cycles > 0.0 ? m.cycles * m.period_s : INFINITY;
    if (tau <= tau_end) return sine_from_rest(m.amplitude_m_s2, m.period_s, m.phase_rad, tau);
    return coast_after(sine_from_rest(m.amplitude_m_s2, m.period_s, m.phase_rad, tau_end), tau - tau_end);
}

MotionSample sample_pulse(const PulseMotion& m, double t) {
    const double phase = m.shape == PulseMotion::Shape::one_sine ? 0.0 : pi / 2.0;
    return sample_sine({m.amplitude_m_s2, m.period_s, phase, m.start_s, 1.0}, t);
}

// d/dt[(t - t0) exp(-s^2)] = (1 - 2 s^2) exp(-s^2) with s = pi f (t - t0): the Ricker shape.
MotionSample sample_ricker(const RickerMotion& m, double t) {
    if (t < 0.0) return {};
    const double k = pi * m.peak_frequency_hz;
    const double s = k * (t - m.center_time_s);
    const double s0 = k * (0.0 - m.center_time_s);
    const double g = std::exp(-s * s);
    const double g0 = std::exp(-s0 * s0);
    MotionSample out;
    out.acceleration_m_s2 = m.amplitude_m_s2 * (1.0 - 2.0 * s * s) * g;
    out.velocity_m_s = m.amplitude_m_s2 * ((t - m.center_time_s) * g + m.center_time_s * g0);
    out.displacement_m = m.amplitude_m_s2 * (-(g - g0) / (2.0 * k * k) + m.center_time_s * g0 * t);
    return out;
}

MotionSample sample_series(const AccelerationSeries& m, double t) {
    const auto& ts = m.time_s;
    if (ts.empty() || t <= ts.front()) return {};
    if (t >= ts.back()) {
        const std::size_t last = ts.size() - 1;
        return coast_after({m.displacement_m[last], m.velocity_m_s[last], 0.0}, t - ts.back());
    }
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin()) - 1;
    const double tau = t - ts[i];
    const double a0 = m.acceleration_m_s2[i];
    const double slope = (m.acceleration_m_s2[i + 1] - a0) / (ts[i + 1] - ts[i]);  // [m/s^3]
    MotionSample out;
    out.acceleration_m_s2 = a0 + slope * tau;
    out.velocity_m_s = m.velocity_m_s[i] + a0 * tau + 0.5 * slope * tau * tau;
    out.displacement_m = m.displacement_m[i] + m.velocity_m_s[i] * tau + 0.5 * a0 * tau * tau + slope * tau * tau * tau / 6.0;
    return out;
}

}  // namespace

AccelerationSeries make_acceleration_series(std::vector<double> time_s, std::vector<double> acceleration_m_s2,
                                            std::string source) {
    if (time_s.size() != acceleration_m_s2.size())
        throw std::invalid_argument(fmt::format("{} times but {} accelerations", time_s.size(), acceleration_m_s2.size()));
    if (time_s.size() < 2) throw std::invalid_argument("an acceleration series needs at least 2 samples");
    AccelerationSeries s;
    s.source = std::move(source);
    s.velocity_m_s.assign(time_s.size(), 0.0);
    s.displacement_m.assign(time_s.size(), 0.0);
    for (std::size_t i = 0; i < time_s.size(); ++i)
        if (!std::isfinite(time_s[i]) || !std::isfinite(acceleration_m_s2[i]))
            throw std::invalid_argument(fmt::format("sample {} is not finite (t = {} s, a = {} m/s^2)", i, time_s[i],
                                                    acceleration_m_s2[i]));
    for (std::size_t i = 0; i + 1 < time_s.size(); ++i) {
        const double h = time_s[i + 1] - time_s[i];
        if (!(h > 0.0))
            throw std::invalid_argument(fmt::format("times must increase: t[{}] = {} s, t[{}] = {} s", i, time_s[i], i + 1,
                                                    time_s[i + 1]));
        const double a0 = acceleration_m_s2[i];
        const double a1 = acceleration_m_s2[i + 1];
        s.velocity_m_s[i + 1] = s.velocity_m_s[i] + 0.5 * (a0 + a1) * h;
        s.displacement_m[i + 1] = s.displacement_m[i] + s.velocity_m_s[i] * h + (a0 / 3.0 + a1 / 6.0) * h * h;
    }
    s.time_s = std::move(time_s);
    s.acceleration_m_s2 = std::move(acceleration_m_s2);
    return s;
}

MotionSample sample(const ComponentMotion& motion, double t_s) {
    struct Visitor {
        double t;
        MotionSample operator()(const RestMotion&) const { return {}; }
        MotionSample operator()(const SineMotion& m) const { return sample_sine(m, t); }
        MotionSample operator()(const PulseMotion& m) const { return sample_pulse(m, t); }
        MotionSample operator()(const RickerMotion& m) const { return sample_ricker(m, t); }
        MotionSample operator()(const AccelerationSeries& m) const { return sample_series(m, t); }
    };
    return std::visit(Visitor{t_s}, motion);
}

std::string describe(const ComponentMotion& motion) {
    struct Visitor {
        std::string operator()(const RestMotion&) const { return "none"; }
        std::string operator()(const SineMotion& m) const {
            return fmt::format("sine {:g} m/s^2, period {:g} s, phase {:g} rad, start {:g} s{}", m.amplitude_m_s2,
                               m.period_s, m.phase_rad, m.start_s,
                               m.cycles > 0 ? fmt::format(", {:g} cycles", m.cycles) : std::string{});
        }
        std::string operator()(const PulseMotion& m) const {
            return fmt::format("{} pulse {:g} m/s^2, period {:g} s, start {:g} s",
                               m.shape == PulseMotion::Shape::one_sine ? "one-sine" : "one-cosine", m.amplitude_m_s2,
                               m.period_s, m.start_s);
        }
        std::string operator()(const RickerMotion& m) const {
            return fmt::format("Ricker {:g} m/s^2, peak frequency {:g} Hz, centre {:g} s", m.amplitude_m_s2,
                               m.peak_frequency_hz, m.center_time_s);
        }
        std::string operator()(const AccelerationSeries& m) const {
            return fmt::format("series of {} samples from {} ({:g} to {:g} s)", m.time_s.size(),
                               m.source.empty() ? "memory" : m.source, m.time_s.front(), m.time_s.back());
        }
    };
    return std::visit(Visitor{}, motion);
}

double peak_acceleration(const ComponentMotion& motion) {
    struct Visitor {
        double operator()(const RestMotion&) const { return 0.0; }
        double operator()(const SineMotion& m) const { return std::abs(m.amplitude_m_s2); }
        double operator()(const PulseMotion& m) const { return std::abs(m.amplitude_m_s2); }
        double operator()(const RickerMotion& m) const { return std::abs(m.amplitude_m_s2); }
        double operator()(const AccelerationSeries& m) const {
            double peak = 0.0;
            for (double a : m.acceleration_m_s2) peak = std::max(peak, std::abs(a));
            return peak;
        }
    };
    return std::visit(Visitor{}, motion);
}

}  // namespace blockdem
