#include "motion/synthetic_motion.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include <fmt/format.h>

#include "motion/linear_oscillator.hpp"
#include "motion/record_processing.hpp"
#include "motion/records/ground_motion_record.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;

// Standard normal numbers from a generator whose output the C++ standard fixes.
class GaussianNoise {
public:
    explicit GaussianNoise(std::uint64_t seed) : engine_(seed) {}
    double next() {
        if (has_spare_) {
            has_spare_ = false;
            return spare_;
        }
        const double u1 = uniform_open();
        const double u2 = uniform_open();
        const double r = std::sqrt(-2.0 * std::log(u1));
        spare_ = r * std::sin(2.0 * pi * u2);
        has_spare_ = true;
        return r * std::cos(2.0 * pi * u2);
    }

private:
    double uniform_open() {  // in (0, 1): 53 random bits, never 0
        return (static_cast<double>(engine_() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
    }
    std::mt19937_64 engine_;
    double spare_ = 0.0;
    bool has_spare_ = false;
};

void check(const SyntheticMotionParameters& p) {
    auto require = [](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(fmt::format("synthetic motion: {}", what));
    };
    require(p.duration_s > 0.0 && p.dt_s > 0.0 && p.duration_s >= 2.0 * p.dt_s, "duration and dt must be > 0, duration >= 2 dt");
    require(p.target_pga_m_s2 > 0.0, "the target PGA must be > 0");
    // Counted as a real number before any cast or allocation (duration = 1e300 s).
    const double samples = std::round(p.duration_s / p.dt_s) + 1.0;
    if (!(samples <= static_cast<double>(max_record_samples)))
        throw std::invalid_argument(fmt::format("synthetic motion: duration {:g} s at dt = {:g} s is {:g} samples; a motion may "
                                                "have at most {}",
                                                p.duration_s, p.dt_s, samples, max_record_samples));
    require(p.ground_frequency_hz > 0.0 && p.ground_damping > 0.0, "ground frequency and damping must be > 0");
    require(p.highpass_frequency_hz >= 0.0 && p.highpass_damping > 0.0, "high-pass frequency must be >= 0 and its damping > 0");
    // A filter above the Nyquist frequency 1 / (2 dt) cannot be sampled (and 1e200 Hz overflows).
    const double nyquist_hz = 0.5 / p.dt_s;
    for (const auto& [name, hz] : {std::pair{"ground_frequency", p.ground_frequency_hz}, std::pair{"highpass_frequency", p.highpass_frequency_hz}})
        if (!(hz < nyquist_hz))
            throw std::invalid_argument(fmt::format("synthetic motion: {} = {:g} Hz must be below the Nyquist frequency 1 / (2 dt) "
                                                    "= {:g} Hz", name, hz, nyquist_hz));
    require(p.ground_damping < 100.0 && p.highpass_damping < 100.0, "the filter damping ratios must be below 100");
    require(p.peak_time_fraction > 0.0 && p.peak_time_fraction < 1.0, "peak_time_fraction must be in (0, 1)");
    require(p.end_level > 0.0 && p.end_level < 1.0, "end_level must be in (0, 1)");
    require(p.rise_time_s >= 0.0 && p.strong_duration_s >= 0.0 && p.rise_time_s + p.strong_duration_s <= p.duration_s,
            "rise_time + strong_duration must fit in the duration");
}

// Drives x'' + 2 zeta w x' + w^2 x = f with the force samples f (exact piecewise-linear steps)
// and returns output(step, state, f) at every sample.
template <class Output>
std::vector<double> oscillator_response(const std::vector<double>& f, double dt, double frequency_hz, double zeta,
                                        Output output) {
    const OscillatorStep step(2.0 * pi * frequency_hz, zeta, dt);
    std::vector<double> out(f.size());
    OscillatorState s;
    for (std::size_t k = 0; k < f.size(); ++k) {
        if (k > 0) s = step.advance(s, f[k - 1], f[k]);
        out[k] = output(step, s, f[k]);
    }
    return out;
}

// Kanai-Tajimi: the absolute acceleration of the filter, -(2 zeta w x' + w^2 x) (= x'' - f),
// which passes the band near w.
std::vector<double> band_filter(const std::vector<double>& f, double dt, double frequency_hz, double zeta) {
    const double w = 2.0 * pi * frequency_hz;
    return oscillator_response(f, dt, frequency_hz, zeta, [w, zeta](const OscillatorStep&, OscillatorState s, double) {
        return -(2.0 * zeta * w * s.v + w * w * s.x);
    });
}

// Clough-Penzien: the relative acceleration y'' of an oscillator driven by f, which removes the
// frequencies below its corner (|H| ~ (w / wf)^2 there) and passes those above.
std::vector<double> high_pass(const std::vector<double>& f, double dt, double frequency_hz, double zeta) {
    return oscillator_response(f, dt, frequency_hz, zeta,
                               [](const OscillatorStep& step, OscillatorState s, double force) { return step.acceleration(s, force); });
}

}  // namespace

EnvelopeShape parse_envelope_shape(std::string_view name) {
    if (name == "saragoni_hart") return EnvelopeShape::saragoni_hart;
    if (name == "trapezoidal") return EnvelopeShape::trapezoidal;
    throw std::invalid_argument(fmt::format("unknown envelope '{}'; use saragoni_hart or trapezoidal", name));
}

// Saragoni-Hart e(t) = (t/(eps T))^b exp(-b (t/(eps T) - 1)): peak 1 at eps T; b is chosen so that
// e(T) = end_level, i.e. b = ln(end_level) / (ln(1/eps) + 1 - 1/eps) after taking logs at t = T.
double envelope_at(const SyntheticMotionParameters& p, double t) {
    if (t <= 0.0) return 0.0;
    if (p.envelope == EnvelopeShape::trapezoidal) {
        if (t < p.rise_time_s) return t / p.rise_time_s;
        const double decay_start = p.rise_time_s + p.strong_duration_s;
        if (t <= decay_start) return 1.0;
        return std::max(0.0, (p.duration_s - t) / (p.duration_s - decay_start));
    }
    const double eps = p.peak_time_fraction;
    const double b = std::log(p.end_level) / (std::log(1.0 / eps) + 1.0 - 1.0 / eps);
    const double x = t / (eps * p.duration_s);
    return std::pow(x, b) * std::exp(-b * (x - 1.0));
}

std::vector<double> synthetic_ground_motion(const SyntheticMotionParameters& p) {
    check(p);
    const auto n = static_cast<std::size_t>(std::round(p.duration_s / p.dt_s)) + 1;  // bounded by check()
    GaussianNoise noise(p.seed);
    std::vector<double> white(n);
    for (double& w : white) w = noise.next();
    std::vector<double> a = band_filter(white, p.dt_s, p.ground_frequency_hz, p.ground_damping);
    if (p.highpass_frequency_hz > 0.0) a = high_pass(a, p.dt_s, p.highpass_frequency_hz, p.highpass_damping);
    for (std::size_t k = 0; k < n; ++k) a[k] *= envelope_at(p, static_cast<double>(k) * p.dt_s);
    const double factor = scale_factor_for_pga(a, p.target_pga_m_s2);
    for (double& x : a) x *= factor;
    return a;
}

}  // namespace blockdem
