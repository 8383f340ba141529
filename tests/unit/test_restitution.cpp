// Calibration of h_n from e in both meanings, checked against a direct integration of the
// no-tension spring-dashpot (independent of the closed forms).
#include <gtest/gtest.h>

#include <cmath>

#include "laws/restitution.hpp"

namespace blockdem {
namespace {

// x'' + 2 h x' + x = 0 from x = 0, x' = 1 (w0 = 1) until the force 2 h x' + x reaches zero;
// classical RK4 with a tiny step; returns the rebound speed.
double integrate_rebound(double h) {
    double x = 0.0, v = 1.0;
    const double dt = 1e-5;
    auto acc = [h](double x_, double v_) { return -2.0 * h * v_ - x_; };
    for (int i = 0; i < 10'000'000; ++i) {
        const double k1x = v, k1v = acc(x, v);
        const double k2x = v + 0.5 * dt * k1v, k2v = acc(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v);
        const double k3x = v + 0.5 * dt * k2v, k3v = acc(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v);
        const double k4x = v + dt * k3v, k4v = acc(x + dt * k3x, v + dt * k3v);
        x += dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (i > 10 && (2.0 * h * v + x <= 0.0 || x <= 0.0)) return std::abs(v);
    }
    return NAN;
}

TEST(Restitution, PaperFormula) {
    EXPECT_NEAR(damping_ratio_paper(0.4), 0.2800, 5e-5);  // the paper's h_n = 0.28 for e = 0.4
    for (double e : {0.1, 0.4, 0.9}) EXPECT_NEAR(restitution_paper(damping_ratio_paper(e)), e, 1e-12);
    EXPECT_DOUBLE_EQ(damping_ratio_paper(1.0), 0.0);
}

TEST(Restitution, NoTensionClosedFormMatchesIntegration) {
    for (double h : {0.05, 0.2, 0.5, 0.7, 0.75, 0.9, 1.0, 1.5, 3.0})
        EXPECT_NEAR(restitution_no_tension(h), integrate_rebound(h), 1e-4) << "h = " << h;
}

TEST(Restitution, ReboundMeaningRoundTrip) {
    for (double e : {0.05, 0.2, 0.4, 0.6, 0.8, 0.99}) {
        const double h = damping_ratio_rebound(e);
        EXPECT_NEAR(restitution_no_tension(h), e, 1e-10);
        EXPECT_GT(h, damping_ratio_paper(e));  // no tension needs more damping for the same e
    }
    EXPECT_DOUBLE_EQ(damping_ratio_rebound(1.0), 0.0);
}

}  // namespace
}  // namespace blockdem
