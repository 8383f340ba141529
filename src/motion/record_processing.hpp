#pragma once
// From a record as read to the acceleration that drives the table: time window, cosine taper,
// baseline correction, amplitude scaling, zero padding, and placement on the simulation's time
// axis. Why each step exists and the order they are applied in: docs/records.md.
//
// Baseline correction. A table driven kinematically needs a, v and u that agree and a table that
// ends at rest near where it started. Integrating a record from rest leaves a velocity drift (a
// small acceleration offset) and a displacement drift. Each correction subtracts from a(t) the
// derivative of a polynomial fitted to the drift, so that v = int a and u = int v stay exact
// integrals (the table never sees inconsistent kinematics), and v(0) = u(0) = 0 stay true:
//   mean                     a -= mean(a)                               (nothing guaranteed)
//   linear                   v -= (v_end / T) t, i.e. a -= v_end / T     (v_end = 0; u not controlled)
//   polynomial (order n)     v -= p(t), p = c1 t + ... + cn t^n          (v_end = 0 and u_end = 0)
//   displacement_polynomial  u -= p(t), p = c2 t^2 + ... + cn t^n        (v_end = 0 and u_end = 0)
// For the polynomial fits, p is the least-squares fit to v (or u) under the two exact constraints
// that the corrected v and u end at zero; order 2 (resp. 3) is fixed by the constraints alone.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace blockdem {

enum class BaselineMethod { none, mean, linear, polynomial, displacement_polynomial };

struct BaselineCorrection {
    BaselineMethod method = BaselineMethod::none;
    int order = 3;  ///< polynomial order: polynomial 2..6, displacement_polynomial 3..6
};

/// "none", "mean", "linear", "polynomial", "displacement_polynomial"; std::invalid_argument otherwise.
BaselineMethod parse_baseline_method(std::string_view name);
std::string_view baseline_method_name(BaselineMethod method);
/// The names, comma-separated, for messages.
std::string baseline_method_names();

/// The corrected acceleration [m/s^2]. Throws std::invalid_argument for an order out of range.
std::vector<double> correct_baseline(std::span<const double> acceleration_m_s2, double dt_s, BaselineCorrection correction);

/// The factor that makes max |a| equal target_pga_m_s2. Throws when the record is all zeros.
double scale_factor_for_pga(std::span<const double> acceleration_m_s2, double target_pga_m_s2);

/// Samples with start_s <= t_k <= start_s + duration_s (t_k = k dt, duration 0 = to the end).
/// Throws std::invalid_argument when fewer than 2 samples remain.
std::vector<double> time_window(std::span<const double> acceleration_m_s2, double dt_s, double start_s, double duration_s);

/// Multiplies the first and last taper_s seconds by a half-cosine ramp from 0 to 1, so that a
/// cut or truncated record starts and ends at zero acceleration.
void apply_cosine_taper(std::vector<double>& acceleration_m_s2, double dt_s, double taper_s);

/// How many zeros pad_s seconds add to a series of `samples` samples; std::invalid_argument with
/// the figures when the padded series would exceed max_record_samples (pad = 1e300 s).
std::size_t padding_samples(std::size_t samples, double dt_s, double pad_s);
/// Appends zeros for pad_s seconds (whole samples), so that blocks can come to rest.
void pad_with_zeros(std::vector<double>& acceleration_m_s2, double dt_s, double pad_s);

/// What to do to a record, in the order it is done.
struct RecordProcessing {
    double start_s = 0.0;                  ///< [s] window start in record time
    double duration_s = 0.0;               ///< [s] window length, 0 = to the end
    double taper_s = 0.0;                  ///< [s] cosine taper at both ends of the window
    double pad_s = 0.0;                    ///< [s] zeros appended to the window
    BaselineCorrection baseline;           ///< over the padded window, so the table ends at rest
    double scale = 1.0;                    ///< amplitude factor (used when no target PGA)
    std::optional<double> target_pga_m_s2; ///< [m/s^2] scale so that the PGA is this (after baseline)
};

/// window -> taper -> pad -> baseline -> scale. Returns the acceleration [m/s^2] at k dt.
std::vector<double> process_record(std::span<const double> acceleration_m_s2, double dt_s, const RecordProcessing& steps);

/// Samples [s] and accelerations [m/s^2] of a resampled record.
struct ResampledRecord {
    std::vector<double> time_s;
    std::vector<double> acceleration_m_s2;
};

/// The record on a grid of step step_s that keeps every original sample as a node: the uniform
/// grid k step_s merged with the sample times k dt (duplicates within 1e-9 dt dropped). The
/// piecewise-linear acceleration through these nodes is the same function as the record's, so
/// every recorded peak is reached at its own time and v, u are unchanged. When dt is a multiple
/// of step_s the grid is uniform. Times start at start_time_s.
ResampledRecord resample_keeping_samples(std::span<const double> acceleration_m_s2, double dt_s, double step_s,
                                         double start_time_s = 0.0);

/// The largest step <= max_step_s that divides dt_s a whole number of times: with it, every
/// record sample falls on a simulation step, so the table reaches each recorded peak exactly.
double step_dividing(double dt_s, double max_step_s);

}  // namespace blockdem
