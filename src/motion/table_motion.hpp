#pragma once
// Prescribed (kinematic) motion of a driven body such as a shaking table.
//
// Every motion is defined by its acceleration a(t) and starts at rest: v(start) = 0 and
// u(start) = 0. Velocity and displacement are the exact integrals of a(t) (closed form for the
// analytic motions, exact piecewise-cubic for a piecewise-linear acceleration series), so the
// table's acceleration, velocity and displacement always agree.
#include <string>
#include <variant>
#include <vector>

namespace blockdem {

/// [m/s^2] The largest peak table acceleration a motion may have: 20 times what any earthquake
/// (the largest recorded, about 4 g), shaking table or centrifuge model (some 50 g at model scale)
/// asks for. Beyond it is a wrong unit or a typed exponent: such a table leaves its blocks behind
/// in the first step, and a peak that overflowed (1e308 g) was reported as a time step too large.
inline constexpr double max_table_acceleration_m_s2 = 1.0e4;

/// Kinematics of one component at one time.
struct MotionSample {
    double displacement_m = 0.0;     ///< [m]
    double velocity_m_s = 0.0;       ///< [m/s]
    double acceleration_m_s2 = 0.0;  ///< [m/s^2]
};

/// No motion.
struct RestMotion {};

/// a(t) = A sin(2 pi (t - start) / T + phase) for start <= t < start + cycles * T (cycles = 0: forever).
struct SineMotion {
    double amplitude_m_s2 = 0.0;  ///< [m/s^2]
    double period_s = 1.0;        ///< [s]
    double phase_rad = 0.0;       ///< [rad]; pi/2 gives A cos(2 pi t / T)
    double start_s = 0.0;         ///< [s]
    double cycles = 0.0;          ///< number of cycles; 0 means no end
};

/// One-sine pulse a = A sin(2 pi tau / T) or one-cosine pulse a = A cos(2 pi tau / T), 0 <= tau <= T.
struct PulseMotion {
    enum class Shape { one_sine, one_cosine };
    Shape shape = Shape::one_sine;
    double amplitude_m_s2 = 0.0;  ///< [m/s^2]
    double period_s = 1.0;        ///< [s]
    double start_s = 0.0;         ///< [s]
};

/// Ricker wavelet a = A (1 - 2 (pi f tau)^2) exp(-(pi f tau)^2), tau = t - center_time.
struct RickerMotion {
    double amplitude_m_s2 = 0.0;    ///< [m/s^2], the peak at tau = 0
    double peak_frequency_hz = 1.0; ///< [Hz]
    double center_time_s = 1.0;     ///< [s]
};

/// Acceleration given at samples (a record), linear between samples, zero after the last one.
/// velocity and displacement at the samples are filled by make_acceleration_series().
struct AccelerationSeries {
    std::vector<double> time_s;              ///< [s], strictly increasing, starting at the motion start
    std::vector<double> acceleration_m_s2;   ///< [m/s^2]
    std::vector<double> velocity_m_s;        ///< [m/s] exact integral at the samples
    std::vector<double> displacement_m;      ///< [m] exact integral at the samples
    std::string source;                      ///< where it came from (file), for messages and reports
};

using ComponentMotion = std::variant<RestMotion, SineMotion, PulseMotion, RickerMotion, AccelerationSeries>;

/// Builds a series from samples and integrates it exactly. Throws std::invalid_argument when the
/// times are not strictly increasing or the sizes differ.
AccelerationSeries make_acceleration_series(std::vector<double> time_s, std::vector<double> acceleration_m_s2,
                                            std::string source = {});

/// The kinematics of one component at time t [s].
MotionSample sample(const ComponentMotion& motion, double t_s);

/// A short human description, e.g. "sine 3.5 m/s^2, T = 1 s".
std::string describe(const ComponentMotion& motion);

/// Peak absolute acceleration [m/s^2] (exact for analytic motions, over the samples for a series).
double peak_acceleration(const ComponentMotion& motion);

/// The motion of a driven body: horizontal (x) and vertical (y) at once.
struct TableMotion {
    ComponentMotion horizontal = RestMotion{};
    ComponentMotion vertical = RestMotion{};
};

}  // namespace blockdem
