#pragma once
// Rocking modes of a block on a harmonically shaken table, the classification behind the
// source paper's finding (Ishiyama 1982; Ohmachi and Arai 1985): a block rocks in phase,
// anti-phase or subharmonically, and only in-phase rocking overturns at the static a/g = b/h.
//
// The rule (docs/rocking_modes.md) reads the rotation theta(t) over a window of W whole table
// periods T at the end of the forcing (the steady state, after the start-up), sampled M = 64
// times per period:
//   1. overturned: the run's monitor says so (rotated beyond the critical angle at the end);
//   2. no rocking in the window (peak |theta| below the rocking threshold): "sliding" when the
//      block slid during the run, else "none";
//   3. the orbit's period: the repeat error e(n) is the RMS of theta(t) - theta(t - n T) over
//      the second half of the window, relative to the RMS of theta - mean there. Taken at one
//      phase, theta(t0 + k T), k = 0, 1, ... is a Poincare section of the motion (sampled once
//      per table period); e(n) measures how far all M sections are from repeating every n
//      points. n* = the smallest n in {1, 2, 3} (2n <= W) with e(n) <= 0.3: a period-1 orbit
//      also repeats after 2 and 3 periods, so the smallest is the orbit's period;
//   4. no such n: "irregular" (chaotic rocking, a longer period, or a start-up not yet over);
//   5. n* >= 2: "subharmonic" (the orbit repeats every n* table periods);
//   6. n* = 1: the phase lag of theta's Fourier component at 1/T behind the table
//      acceleration's: |lag| < 90 deg "in_phase" (the block leans the way the inertia force
//      -m a pushes it when the acceleration peaks; theta counter-clockwise, i.e. leaning to -x,
//      is in phase with a > 0), else "anti_phase".
// For a table motion that is not a sine the harmonic sub-modes have no meaning; rocking is then
// reported as "rocking".
#include <array>
#include <string>
#include <vector>

#include "motion/table_motion.hpp"
#include "world/world.hpp"

namespace blockdem {

enum class RockingMode { none, sliding, in_phase, anti_phase, subharmonic, irregular, rocking, overturned };

/// The name written to tables: "none", "sliding", "in_phase", ...
std::string to_string(RockingMode mode);

/// The analysis window: W whole periods of a sine table motion, sampled M times per period.
struct RockingWindow {
    double period_s = 1.0;         ///< [s] table period T
    double start_s = 0.0;          ///< [s] window start (a whole number of periods after the sine starts)
    int cycles = 0;                ///< W; 0: no window (motion not harmonic or too short)
    int samples_per_cycle = 64;    ///< M

    double sample_interval_s() const { return period_s / samples_per_cycle; }
    double end_s() const { return start_s + cycles * period_s; }
    bool valid() const { return cycles > 0; }
};

/// The window for a horizontal sine motion over a run of duration_s: the last W whole forcing
/// periods, W the largest multiple of 6 that is at most 60% of the forcing periods available
/// (so that n = 1, 2 and 3 all fit), or half of them when fewer than 10 are available. Invalid
/// (cycles = 0) when fewer than 2 whole periods are available.
RockingWindow rocking_window(const SineMotion& sine, double duration_s);

/// Everything the rule needs, measured elsewhere.
struct RockingSignal {
    RockingWindow window;
    std::vector<double> theta_rad;            ///< [rad] theta at start + k * interval, k < W * M
    std::vector<double> table_acceleration_m_s2;  ///< [m/s^2] at the same times
    double rocking_threshold_rad = 0.0;       ///< [rad] rotation that counts as rocking
    bool overturned = false;
    bool slid = false;    ///< slid during the run
    bool rocked = false;  ///< rocked during the run (used when there is no window)
};

/// The longest orbit the rule looks for, in table periods.
inline constexpr int max_period_ratio = 3;

struct RockingClassification {
    RockingMode mode = RockingMode::none;
    int period_ratio = 0;           ///< n*: orbit period / table period (0 when not rocking or irregular)
    double phase_lag_rad = 0.0;     ///< [rad] lag of theta behind the table acceleration (n* = 1)
    double periodicity_error = 0.0; ///< [-] e(n*); irregular: the smallest e(n)
    /// [-] e(n) for n = 1, 2, 3: the relative RMS of theta(t) - theta(t - n T); -1 where n
    /// does not fit the window twice.
    std::array<double, max_period_ratio> repeat_error{-1.0, -1.0, -1.0};
    double impacts_per_period = 0.0;  ///< [-] sign changes of theta in the window / W
};

/// Applies the rule above. Without a valid window the result is none / sliding / rocking /
/// overturned from the flags alone.
RockingClassification classify_rocking_mode(const RockingSignal& signal);

/// Watches every dynamic body during a run and samples its rotation in the window. (Base slip,
/// overturning and rocking flags come from ResponseMonitor.)
class RockingModeObserver {
public:
    /// window.valid() false: no samples are kept (non-harmonic motion).
    RockingModeObserver(const World& w, RockingWindow window);
    /// Called once per step with the state at t.
    void observe(const World& w);
    /// The signal of body i, to be completed with the threshold and the flags.
    RockingSignal signal_of(std::size_t body) const;

private:
    RockingWindow window_;
    std::size_t next_sample_ = 0;
    std::vector<std::vector<double>> theta_rad_;  ///< per body, the window samples
    std::vector<double> table_acceleration_m_s2_;
};

}  // namespace blockdem
