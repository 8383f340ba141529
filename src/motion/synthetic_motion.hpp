#pragma once
// A synthetic, earthquake-like ground acceleration for machines without record files:
// Gaussian white noise filtered by the Kanai-Tajimi soil filter (a damped oscillator of the
// ground's frequency and damping; Kanai 1957, Tajimi 1960), then by the Clough-Penzien high-pass
// filter (a second oscillator that removes the low frequencies that make the Kanai-Tajimi motion
// drift in velocity and displacement), multiplied by a time envelope, and scaled to a target PGA.
//
// Reproducible: the same parameters and seed give the same record on every platform, because
// the noise uses std::mt19937_64 (its output is fixed by the standard) and our own Box-Muller
// transform (std::normal_distribution is implementation-defined), and the filters are exact.
#include <cstdint>
#include <string_view>
#include <vector>

namespace blockdem {

enum class EnvelopeShape { saragoni_hart, trapezoidal };

/// "saragoni_hart" or "trapezoidal"; std::invalid_argument otherwise.
EnvelopeShape parse_envelope_shape(std::string_view name);

struct SyntheticMotionParameters {
    std::uint64_t seed = 1;
    double duration_s = 20.0;              ///< [s]
    double dt_s = 0.01;                    ///< [s] sample interval of the generated record
    double target_pga_m_s2 = 3.0;          ///< [m/s^2]
    double ground_frequency_hz = 2.5;      ///< [Hz] Kanai-Tajimi (firm ground: 15.6 rad/s)
    double ground_damping = 0.6;           ///< Kanai-Tajimi damping ratio
    double highpass_frequency_hz = 0.2;    ///< [Hz] Clough-Penzien corner; 0 switches it off
    double highpass_damping = 0.6;         ///< Clough-Penzien damping ratio
    EnvelopeShape envelope = EnvelopeShape::saragoni_hart;
    double peak_time_fraction = 0.2;       ///< Saragoni-Hart: the envelope peaks at this fraction of the duration
    double end_level = 0.05;               ///< Saragoni-Hart: envelope value at the end (peak = 1)
    double rise_time_s = 2.0;              ///< [s] trapezoidal: ramp up
    double strong_duration_s = 8.0;        ///< [s] trapezoidal: flat part; then a ramp down to the end
};

/// Envelope value (peak 1) at time t [s].
double envelope_at(const SyntheticMotionParameters& p, double t_s);

/// The acceleration [m/s^2] at t_k = k dt, k = 0 .. round(duration / dt). Throws
/// std::invalid_argument for parameters out of range.
std::vector<double> synthetic_ground_motion(const SyntheticMotionParameters& p);

}  // namespace blockdem
