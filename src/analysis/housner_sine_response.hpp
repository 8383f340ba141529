#pragma once
// The steady response of Housner's block (analysis/housner_rocking) to a sine table motion,
// classified by the same rule as a DEM run (analysis/rocking_mode): one point of a mode map.
//
// Why a separate step: an orbit's period is only seen after the start-up has died out, and the
// rule needs theta at fixed phases of the table period. The block starts at rest, upright, as
// on a shaking table, and the sine a(t) = A sin(2 pi t / T) starts at t = 0; theta is sampled
// (linearly interpolated between RK4 steps) M times per period over the rule's window, the last
// W whole periods. The Poincare section is the state (theta, theta') at the start of each
// window period (table phase 0): a period-n orbit repeats it every n points.
#include <vector>

#include "analysis/housner_rocking.hpp"
#include "analysis/rocking_mode.hpp"

namespace blockdem {

struct HousnerSineCase {
    double frequency_hz = 1.0;     ///< [Hz] table frequency 1/T
    double amplitude_m_s2 = 0.0;   ///< [m/s^2] peak table acceleration A
    int cycles = 60;               ///< table periods run
    double dt_s = 1.0e-4;          ///< [s] RK4 step
};

struct HousnerSineResponse {
    RockingClassification classification;
    bool overturned = false;             ///< |theta| reached 90 deg
    double peak_abs_theta_rad = 0.0;     ///< [rad] over the whole run
    std::vector<RockingPoint> poincare_section;  ///< state at the start of each window period
    int impacts_in_window = 0;           ///< impacts (theta = 0 crossings) inside the window
};

/// theta and the table acceleration at the window's sample times, from a Housner history
/// (linear interpolation between steps). Empty samples when the window is invalid or the block
/// overturned.
RockingSignal housner_rocking_signal(const RockingResult& result, const ComponentMotion& base, const RockingWindow& window);

/// Runs the case and classifies its window. Throws std::invalid_argument for a frequency,
/// amplitude, cycle count or step that is not positive and finite.
HousnerSineResponse housner_sine_response(const HousnerBlock& block, const HousnerSineCase& sine_case);

}  // namespace blockdem
