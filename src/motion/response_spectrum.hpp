#pragma once
// Elastic response spectrum of a ground acceleration: the peak relative displacement Sd of a
// damped linear oscillator u'' + 2 zeta omega u' + omega^2 u = -a_g(t), and the pseudo-spectral
// velocity omega Sd and pseudo-acceleration omega^2 Sd.
//
// a_g is the piecewise-linear interpolant of the samples (the same function that drives the
// table). Two integrators: the exact solution for piecewise-linear input (Nigam and Jennings,
// 1969, here via the exponential of the augmented system, see linear_oscillator.hpp) and
// Newmark's constant average acceleration (gamma = 1/2, beta = 1/4). Steps are subdivided to at
// most T/50 so that peaks between samples are seen, and the oscillator keeps vibrating freely for
// one period after the record ends, where the largest response of long periods can occur.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace blockdem {

enum class SpectrumMethod { exact_piecewise_linear, newmark_average_acceleration };

/// "exact" or "newmark"; std::invalid_argument otherwise.
SpectrumMethod parse_spectrum_method(std::string_view name);

struct SpectrumOptions {
    double damping_ratio = 0.05;    ///< fraction of critical damping
    std::vector<double> periods_s;  ///< [s]; empty = default_spectrum_periods(); T = 0 gives the PGA
    SpectrumMethod method = SpectrumMethod::exact_piecewise_linear;
};

struct SpectrumOrdinate {
    double period_s = 0.0;   ///< [s]
    double sd_m = 0.0;       ///< [m] peak relative displacement
    double psv_m_s = 0.0;    ///< [m/s] omega Sd
    double psa_m_s2 = 0.0;   ///< [m/s^2] omega^2 Sd
};

/// [s] The periods a spectrum is computed for, besides T = 0 (the PGA): from 0.001 s, stiffer
/// than any structure (the response is the PGA), to 100 s, longer than the tallest building's
/// and a base-isolated structure's periods. Outside them the oscillator is not physical and its
/// integration would not end (1e-200 s) or would step through a whole record per period.
inline constexpr double min_spectrum_period_s = 1e-3;
inline constexpr double max_spectrum_period_s = 100.0;

/// The period itself when it is 0 or within min..max_spectrum_period_s; std::invalid_argument
/// naming it otherwise.
double checked_spectrum_period(double period_s);

/// count periods from min to max [s], equally spaced in log(T).
std::vector<double> log_spaced_periods(double min_s, double max_s, std::size_t count);
/// 0.01 s to 10 s, 100 periods equally spaced in log(T).
std::vector<double> default_spectrum_periods();

/// The spectrum of acceleration [m/s^2] sampled at dt [s]. Every period is checked first
/// (checked_spectrum_period), so a bad one is refused before any work.
std::vector<SpectrumOrdinate> response_spectrum(std::span<const double> acceleration_m_s2, double dt_s,
                                                const SpectrumOptions& options = {});

/// Peak |u| [m] of one oscillator (period [s], damping ratio), by the chosen method.
double peak_oscillator_displacement(std::span<const double> acceleration_m_s2, double dt_s, double period_s,
                                    double damping_ratio, SpectrumMethod method);

}  // namespace blockdem
