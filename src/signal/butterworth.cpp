#include "signal/butterworth.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace blockdem {
namespace {

using std::numbers::pi;

// The analog section 1 / ((s/w)^2 + 2 zeta (s/w) + 1) through the bilinear transform, with
// K = w T / 2 = tan(pi fc T) (the prewarped cut-off). The numerator, K^2 (1 + 1/z)^2 / a0, is
// taken from the rounded denominator, 1 + a1 + a2 = 4 K^2 / a0, so that the gain at zero
// frequency is 1 to rounding: with fc T small that sum cancels to a few digits, and a position
// channel of 100 m would otherwise come out off by nanometres.
SecondOrderSection bilinear_second_order(double zeta, double k) {
    const double a0 = 1.0 + 2.0 * zeta * k + k * k;
    const double a1 = (2.0 * k * k - 2.0) / a0;
    const double a2 = (1.0 - 2.0 * zeta * k + k * k) / a0;
    const double gain = 0.25 * (1.0 + a1 + a2);
    return {gain, 2.0 * gain, gain, a1, a2};
}

// The analog section 1 / (s/w + 1), likewise: K (1 + 1/z) / (1 + K), with 1 + a1 = 2 K / (1 + K).
SecondOrderSection bilinear_first_order(double k) {
    const double a1 = (k - 1.0) / (1.0 + k);
    const double gain = 0.5 * (1.0 + a1);
    return {gain, gain, 0.0, a1, 0.0};
}

std::complex<double> section_response(const SecondOrderSection& s, std::complex<double> z_inv) {
    const std::complex<double> num = s.b0 + z_inv * (s.b1 + z_inv * s.b2);
    const std::complex<double> den = 1.0 + z_inv * (s.a1 + z_inv * s.a2);
    return num / den;
}

}  // namespace

ButterworthDesign design_butterworth_lowpass(double cutoff_hz, int order, double sample_rate_hz) {
    if (!(sample_rate_hz > 0.0) || !(cutoff_hz > 0.0) || !(cutoff_hz < 0.5 * sample_rate_hz))
        throw std::invalid_argument("the cut-off must lie between 0 and the Nyquist frequency (half the sample rate)");
    if (order < 1 || order > 16) throw std::invalid_argument("the order must be 1 to 16");
    ButterworthDesign d{cutoff_hz, order, sample_rate_hz, {}};
    const double k = std::tan(pi * cutoff_hz / sample_rate_hz);
    // Conjugate pole pairs at angles (2j - 1) pi / (2n) from the imaginary axis: damping
    // zeta_j = sin of that angle.
    for (int j = 1; j <= order / 2; ++j)
        d.sections.push_back(bilinear_second_order(std::sin((2.0 * j - 1.0) * pi / (2.0 * order)), k));
    if (order % 2 == 1) d.sections.push_back(bilinear_first_order(k));
    return d;
}

double magnitude_response(const ButterworthDesign& design, double frequency_hz) {
    const std::complex<double> z_inv = std::polar(1.0, -2.0 * pi * frequency_hz / design.sample_rate_hz);
    std::complex<double> h = 1.0;
    for (const SecondOrderSection& s : design.sections) h *= section_response(s, z_inv);
    return std::abs(h);
}

double analog_butterworth_magnitude(double frequency_hz, double cutoff_hz, int order) {
    return 1.0 / std::sqrt(1.0 + std::pow(frequency_hz / cutoff_hz, 2.0 * order));
}

double dc_group_delay_s(const ButterworthDesign& design) {
    // At w = 0 the delay of B(z)/A(z) in samples is sum(k b_k)/sum(b_k) - sum(k a_k)/sum(a_k).
    double samples = 0.0;
    for (const SecondOrderSection& s : design.sections) {
        samples += (s.b1 + 2.0 * s.b2) / (s.b0 + s.b1 + s.b2);
        samples -= (s.a1 + 2.0 * s.a2) / (1.0 + s.a1 + s.a2);
    }
    return samples / design.sample_rate_hz;
}

double analog_dc_group_delay_s(double cutoff_hz, int order) {
    return 1.0 / (2.0 * pi * cutoff_hz * std::sin(pi / (2.0 * order)));
}

ButterworthChannel::ButterworthChannel(const ButterworthDesign& design)
    : sections_(design.sections), state_(2 * design.sections.size(), 0.0) {}

double ButterworthChannel::filter(double x) {
    if (!started_) {
        // Each section has unit gain at zero frequency: y = x in the steady state.
        for (std::size_t i = 0; i < sections_.size(); ++i) {
            const SecondOrderSection& s = sections_[i];
            state_[2 * i + 1] = (s.b2 - s.a2) * x;
            state_[2 * i] = (s.b1 - s.a1) * x + state_[2 * i + 1];
        }
        started_ = true;
    }
    double v = x;
    for (std::size_t i = 0; i < sections_.size(); ++i) {
        const SecondOrderSection& s = sections_[i];
        double& s1 = state_[2 * i];
        double& s2 = state_[2 * i + 1];
        const double y = s.b0 * v + s1;
        s1 = s.b1 * v - s.a1 * y + s2;
        s2 = s.b2 * v - s.a2 * y;
        v = y;
    }
    return v;
}

void ButterworthChannel::restore(const std::vector<double>& state, bool started) {
    if (state.size() != state_.size()) throw std::invalid_argument("the saved filter state has another number of sections");
    state_ = state;
    started_ = started;
}

}  // namespace blockdem
