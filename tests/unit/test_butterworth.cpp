// The Butterworth low-pass of the sensors (signal/butterworth.hpp): its magnitude against the
// ideal |H| = 1 / sqrt(1 + (f/fc)^(2n)), its steady-state gain on sines, and its delay.
//
// Tolerances, and why: the bilinear transform maps f to tan(pi f T) / (pi T), so the digital
// filter equals the warped ideal to rounding (1e-12) and the unwarped one only while f << 1/T:
// at f = 1/20 T the frequency is off by 0.8%, which moves |H| by at most 1e-3 there. A sine's
// steady amplitude, read after 40 periods of transient, is within 2e-3 of |H| (the sampled
// peak misses the true peak by at most 1 - cos(pi f T) = 5e-5, the rest is the transient).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "signal/butterworth.hpp"

namespace blockdem {
namespace {

using std::numbers::pi;
constexpr double sample_rate_hz = 10000.0;   // dt = 1e-4 s, as in the paper's cases

TEST(Butterworth, MagnitudeIsTheWarpedIdealAndTheIdealAtLowFrequency) {
    for (int order : {1, 2, 3, 4, 5, 8}) {
        const double fc = 50.0;
        const ButterworthDesign d = design_butterworth_lowpass(fc, order, sample_rate_hz);
        EXPECT_EQ(d.sections.size(), static_cast<std::size_t>((order + 1) / 2));
        EXPECT_NEAR(magnitude_response(d, 0.0), 1.0, 1e-12) << "order " << order;
        EXPECT_NEAR(magnitude_response(d, fc), 1.0 / std::sqrt(2.0), 1e-12) << "order " << order;
        for (double f : {1.0, 10.0, 25.0, 40.0, 60.0, 100.0, 200.0, 500.0, 2000.0, 4900.0}) {
            const double warped = std::tan(pi * f / sample_rate_hz) / std::tan(pi * fc / sample_rate_hz);
            EXPECT_NEAR(magnitude_response(d, f), 1.0 / std::sqrt(1.0 + std::pow(warped, 2.0 * order)), 1e-12)
                << "order " << order << ", f " << f;
            if (f <= sample_rate_hz / 20.0)
                EXPECT_NEAR(magnitude_response(d, f), analog_butterworth_magnitude(f, fc, order), 1e-3)
                    << "order " << order << ", f " << f;
        }
    }
}

// Filters a sine of frequency f for 60 periods and returns the largest |output| over the last 20.
double steady_amplitude(const ButterworthDesign& d, double f) {
    ButterworthChannel channel(d);
    const auto per_period = static_cast<int>(std::lround(sample_rate_hz / f));
    double peak = 0.0;
    for (int k = 0; k < 60 * per_period; ++k) {
        const double y = channel.filter(std::sin(2.0 * pi * f * k / sample_rate_hz));
        if (k >= 40 * per_period) peak = std::max(peak, std::abs(y));
    }
    return peak;
}

TEST(Butterworth, SteadyStateSineGainIsTheMagnitude) {
    for (int order : {2, 4, 5}) {
        const ButterworthDesign d = design_butterworth_lowpass(50.0, order, sample_rate_hz);
        for (double f : {10.0, 25.0, 50.0, 100.0, 200.0}) {
            const double gain = steady_amplitude(d, f);
            EXPECT_NEAR(gain, magnitude_response(d, f), 2e-3) << "order " << order << ", f " << f;
            EXPECT_NEAR(gain, analog_butterworth_magnitude(f, 50.0, order), 3e-3) << "order " << order << ", f " << f;
        }
    }
}

TEST(Butterworth, LowFrequencyDelayIsTheGroupDelay) {
    for (int order : {2, 4}) {
        const double fc = 50.0;
        const ButterworthDesign d = design_butterworth_lowpass(fc, order, sample_rate_hz);
        const double analog = analog_dc_group_delay_s(fc, order);
        EXPECT_NEAR(dc_group_delay_s(d), analog, 0.01 * analog) << "order " << order;
        // A slow ramp comes out late by the group delay once the transient has died out.
        ButterworthChannel channel(d);
        double y = 0.0;
        const int steps = 4000;
        for (int k = 0; k <= steps; ++k) y = channel.filter(static_cast<double>(k) / sample_rate_hz);
        const double lag_s = static_cast<double>(steps) / sample_rate_hz - y;
        EXPECT_NEAR(lag_s, dc_group_delay_s(d), 1e-3 * dc_group_delay_s(d)) << "order " << order;
    }
    // The formula's values quoted in the docs.
    EXPECT_NEAR(analog_dc_group_delay_s(1.0, 2), 0.225, 5e-4);
    EXPECT_NEAR(analog_dc_group_delay_s(1.0, 4), 0.416, 5e-4);
}

// A constant starts in the steady state: no transient. (The poles of a 20 Hz filter at 10 kHz
// sit within 0.013 of z = 1, so the sections amplify their own rounding at low frequency by
// about 1 / (1 + a1 + a2) = 6e4: 1e-16 per step becomes up to 1e-11 of the value, 1e-10 allowed.)
TEST(Butterworth, ConstantInputPassesWithoutTransient) {
    ButterworthChannel channel(design_butterworth_lowpass(20.0, 4, sample_rate_hz));
    for (int k = 0; k < 20000; ++k) ASSERT_NEAR(channel.filter(2.7), 2.7, 1e-10 * 2.7) << "step " << k;
}

TEST(Butterworth, RefusesACutOffAtOrAboveNyquist) {
    EXPECT_THROW(design_butterworth_lowpass(5000.0, 2, sample_rate_hz), std::invalid_argument);
    EXPECT_THROW(design_butterworth_lowpass(0.0, 2, sample_rate_hz), std::invalid_argument);
    EXPECT_THROW(design_butterworth_lowpass(50.0, 0, sample_rate_hz), std::invalid_argument);
}

}  // namespace
}  // namespace blockdem
