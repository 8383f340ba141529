#pragma once
// A digital Butterworth low-pass filter, as real accelerometer channels are filtered: the
// analog prototype of order n (poles evenly spaced on the left half of the unit circle),
// its cut-off prewarped (w_a = 2/T tan(pi fc T)) so that the digital filter is -3 dB exactly
// at fc, mapped to z by the bilinear transform s = 2/T (1 - 1/z)/(1 + 1/z), and run as cascaded
// second-order sections (one first-order section for odd n) in transposed direct form II,
// which keeps every section well conditioned at high orders and low fc T.
//
// Magnitude: |H(f)| = 1 / sqrt(1 + (tan(pi f T) / tan(pi fc T))^(2n)), which is the analog
// 1 / sqrt(1 + (f/fc)^(2n)) while f << 1/T. Phase: causal, so the output lags the input; at low
// frequency the lag is a pure delay, the group delay at f = 0: 1 / (2 pi fc sin(pi / (2n))) for
// the analog prototype (n = 2: 0.225/fc; n = 4: 0.416/fc), which dc_group_delay_s() gives for the
// digital filter exactly.
#include <cstddef>
#include <vector>

namespace blockdem {

/// y[k] = b0 x[k] + b1 x[k-1] + b2 x[k-2] - a1 y[k-1] - a2 y[k-2] (a0 = 1).
struct SecondOrderSection {
    double b0 = 1.0, b1 = 0.0, b2 = 0.0;
    double a1 = 0.0, a2 = 0.0;
};

struct ButterworthDesign {
    double cutoff_hz = 0.0;      ///< [Hz] -3 dB frequency
    int order = 2;               ///< n >= 1
    double sample_rate_hz = 0.0; ///< [Hz] 1/dt
    std::vector<SecondOrderSection> sections;
};

/// Designs the filter; requires 0 < cutoff_hz < sample_rate_hz / 2 and 1 <= order <= 16
/// (std::invalid_argument otherwise).
ButterworthDesign design_butterworth_lowpass(double cutoff_hz, int order, double sample_rate_hz);

/// |H| of the digital filter at frequency_hz, from its sections.
double magnitude_response(const ButterworthDesign& design, double frequency_hz);
/// The ideal Butterworth magnitude 1 / sqrt(1 + (f/fc)^(2n)).
double analog_butterworth_magnitude(double frequency_hz, double cutoff_hz, int order);
/// [s] group delay of the digital filter at zero frequency (how far the output lags a slow input).
double dc_group_delay_s(const ButterworthDesign& design);
/// [s] the analog prototype's group delay at zero frequency, 1 / (2 pi fc sin(pi / (2n))).
double analog_dc_group_delay_s(double cutoff_hz, int order);

/// The running filter of one channel: the design's sections and their two states each.
class ButterworthChannel {
public:
    explicit ButterworthChannel(const ButterworthDesign& design);
    /// Filters the next sample. The first sample sets every state to the steady state of a
    /// constant input equal to it, so a channel that starts away from zero (a position) starts
    /// without a transient.
    double filter(double x);
    /// The running state (two per section) and whether the first sample came, for a state file.
    const std::vector<double>& state() const { return state_; }
    bool started() const { return started_; }
    /// Continues from a saved state(); its size must be state()'s (std::invalid_argument).
    void restore(const std::vector<double>& state, bool started);

private:
    std::vector<SecondOrderSection> sections_;
    std::vector<double> state_;   ///< two per section
    bool started_ = false;
};

}  // namespace blockdem
