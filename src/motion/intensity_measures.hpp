#pragma once
// Intensity measures of an acceleration record sampled at a constant step, with the
// conventions of docs/records.md (the same as the data set's sidecar files): t_k = k dt; PGA is
// the first sample reaching max |a|; velocity by the trapezoid rule from rest; displacement by
// the exact integral of the piecewise-linear acceleration (what the table does); Arias intensity
// by the trapezoid rule on a^2 with g = 9.80665 m/s^2; durations from the first sample whose
// cumulative Arias fraction reaches 5 %, 75 %, 95 % (no interpolation).
#include <cstddef>
#include <span>
#include <vector>

namespace blockdem {

struct IntensityMeasures {
    double pga_m_s2 = 0.0;            ///< [m/s^2] max |a|
    double pga_signed_m_s2 = 0.0;     ///< [m/s^2] a at the peak, with its sign
    double pga_time_s = 0.0;          ///< [s]
    double pgv_m_s = 0.0;             ///< [m/s] max |v|
    double pgv_time_s = 0.0;          ///< [s]
    double pgd_m = 0.0;               ///< [m] max |u|
    double pgd_time_s = 0.0;          ///< [s]
    double final_velocity_m_s = 0.0;  ///< [m/s] v at the last sample (drift of the velocity)
    double final_displacement_m = 0.0;///< [m] u at the last sample (drift of the table)
    double arias_m_s = 0.0;           ///< [m/s] Arias intensity pi/(2 g) int a^2 dt
    double t5_s = 0.0;                ///< [s] time when 5 % of the Arias intensity is reached
    double t75_s = 0.0;               ///< [s]
    double t95_s = 0.0;               ///< [s]
    double d5_95_s = 0.0;             ///< [s] significant duration t95 - t5
    double d5_75_s = 0.0;             ///< [s] t75 - t5
    double bracketed_duration_s = 0.0;///< [s] first to last |a| >= 0.05 g
};

/// Velocity [m/s] and displacement [m] at the samples, from rest, integrated exactly as the table
/// motion integrates a piecewise-linear acceleration (trapezoid for v, cubic for u).
struct RecordKinematics {
    std::vector<double> velocity_m_s;
    std::vector<double> displacement_m;
};
RecordKinematics integrate_record(std::span<const double> acceleration_m_s2, double dt_s);

/// All measures of one record. acceleration in m/s^2, dt in s; at least 2 samples.
IntensityMeasures intensity_measures(std::span<const double> acceleration_m_s2, double dt_s);

}  // namespace blockdem
