// Table motions: velocity and displacement are the exact integrals of the acceleration.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "motion/table_motion.hpp"

namespace blockdem {
namespace {

// Checks v = integral of a and u = integral of v by Simpson's rule on a fine grid.
void expect_consistent(const ComponentMotion& m, double end_s) {
    const int n = 20000;
    const double h = end_s / n;
    double v = 0.0, u = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = i * h;
        const MotionSample a = sample(m, t), b = sample(m, t + 0.5 * h), c = sample(m, t + h);
        v += h / 6.0 * (a.acceleration_m_s2 + 4 * b.acceleration_m_s2 + c.acceleration_m_s2);
        u += h / 6.0 * (a.velocity_m_s + 4 * b.velocity_m_s + c.velocity_m_s);
    }
    const MotionSample end = sample(m, end_s);
    const double scale = std::max(1.0, peak_acceleration(m));
    EXPECT_NEAR(end.velocity_m_s, v, 1e-6 * scale) << describe(m);
    EXPECT_NEAR(end.displacement_m, u, 1e-6 * scale) << describe(m);
}

TEST(TableMotion, AnalyticMotionsAreSelfConsistent) {
    expect_consistent(SineMotion{3.5, 1.0, std::numbers::pi / 2, 0.0, 0.0}, 2.7);
    expect_consistent(SineMotion{2.0, 0.4, 0.3, 0.5, 3.0}, 3.0);
    expect_consistent(PulseMotion{PulseMotion::Shape::one_sine, 4.9, 1.0, 0.2}, 2.0);
    // The one-cosine pulse ends with a jump of A: integrate up to it; after it the table coasts.
    const PulseMotion cosine{PulseMotion::Shape::one_cosine, 4.9, 0.5, 0.0};
    expect_consistent(cosine, 0.5);
    EXPECT_NEAR(sample(cosine, 1.5).velocity_m_s, sample(cosine, 0.5).velocity_m_s, 1e-12);
    EXPECT_NEAR(sample(cosine, 1.5).displacement_m,
                sample(cosine, 0.5).displacement_m + sample(cosine, 0.5).velocity_m_s * 1.0, 1e-12);
    expect_consistent(RickerMotion{3.0, 2.0, 1.0}, 2.5);
    expect_consistent(make_acceleration_series({0.0, 0.1, 0.3, 0.35, 1.0}, {0.0, 2.0, -1.0, 0.5, 0.0}), 1.5);
}

TEST(TableMotion, PaperCosineTable) {
    // 350 cos(2 pi t) gal from rest: x = 3.5 / (2 pi)^2 (1 - cos 2 pi t).
    const SineMotion m{3.5, 1.0, std::numbers::pi / 2, 0.0, 0.0};
    const double w = 2 * std::numbers::pi;
    for (double t : {0.1, 0.5, 0.77}) {
        EXPECT_NEAR(sample(m, t).acceleration_m_s2, 3.5 * std::cos(w * t), 1e-12);
        EXPECT_NEAR(sample(m, t).displacement_m, 3.5 / (w * w) * (1 - std::cos(w * t)), 1e-12);
    }
}

TEST(TableMotion, OneSinePulseEndsWithPeersDisplacement) {
    // After a one-sine pulse v(T) = 0 and u(T) = A T^2 / (2 pi); the table then stays there.
    const PulseMotion m{PulseMotion::Shape::one_sine, 4.905, 1.0, 0.0};
    EXPECT_NEAR(sample(m, 1.0).velocity_m_s, 0.0, 1e-12);
    EXPECT_NEAR(sample(m, 3.0).displacement_m, 4.905 / (2 * std::numbers::pi), 1e-12);
}

TEST(TableMotion, SeriesRejectsBadTimes) {
    EXPECT_THROW(make_acceleration_series({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
    EXPECT_THROW(make_acceleration_series({0.0, 1.0}, {1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace blockdem
