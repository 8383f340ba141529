// The 3-D shear slider (laws/coulomb_slider_3d.hpp) driven through load, slip, reversal and a
// falling cap against hand-computed forces; and the history carried into a turned contact frame.
#include <gtest/gtest.h>

#include <cmath>

#include "laws/coulomb_slider_3d.hpp"

namespace blockdem {
namespace {

void expect_vec_near(Vec3 a, Vec3 b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(CoulombSlider3d, LoadSlipReversal) {
    const double ks = 1000.0, limit = 10.0, dt = 1.0;
    ShearHistory3d h;
    // Load: slip increment (2, 1) mm: the spring holds -ks du = (-2, -1) N, below the cap.
    ShearForce3d f = coulomb_slider_3d(ks, 0.0, limit, {0.002, 0.001, 0.0}, h, dt);
    EXPECT_FALSE(f.sliding);
    expect_vec_near(f.spring_n, {-2.0, -1.0, 0.0}, 1e-12);
    h = {f.spring_n, f.dashpot_n};
    f = coulomb_slider_3d(ks, 0.0, limit, {0.006, 0.003, 0.0}, h, dt);
    EXPECT_FALSE(f.sliding);
    expect_vec_near(f.spring_n, {-8.0, -4.0, 0.0}, 1e-12);
    h = {f.spring_n, f.dashpot_n};
    // Slip: the trial (-12, -6) is longer than 10 N: capped along itself, (-2, -1) 10 / sqrt(5).
    // Friction takes the trapezoidal work less the spring's gain: 0.5 (8+8.944, 4+4.472) . (4, 2) mm
    // - (100 - 80) / 2000 = 0.042361 - 0.01 J.
    f = coulomb_slider_3d(ks, 0.0, limit, {0.004, 0.002, 0.0}, h, dt);
    EXPECT_TRUE(f.sliding);
    const double s5 = std::sqrt(5.0);
    expect_vec_near(f.spring_n, {-20.0 / s5, -10.0 / s5, 0.0}, 1e-12);
    expect_vec_near(f.total_n, f.spring_n, 0.0);
    EXPECT_NEAR(f.friction_work_j, 0.5 * (0.004 * (8.0 + 20.0 / s5) + 0.002 * (4.0 + 10.0 / s5)) - 0.01, 1e-12);
    EXPECT_GT(f.friction_work_j, 0.0);
    h = {f.spring_n, f.dashpot_n};
    // Reversal across: slip (0, -5) mm takes the spring off the cap, (-8.944, 0.528): it sticks.
    f = coulomb_slider_3d(ks, 0.0, limit, {0.0, -0.005, 0.0}, h, dt);
    EXPECT_FALSE(f.sliding);
    expect_vec_near(f.spring_n, {-20.0 / s5, -10.0 / s5 + 5.0, 0.0}, 1e-12);
    h = {f.spring_n, f.dashpot_n};
    // The cap falls to 5 N with no slip: the spring relaxes onto it, the excess to friction.
    f = coulomb_slider_3d(ks, 0.0, 5.0, {}, h, dt);
    EXPECT_TRUE(f.sliding);
    EXPECT_NEAR(length(f.spring_n), 5.0, 1e-12);
    EXPECT_NEAR(f.friction_work_j, 0.5 * (dot(h.spring_n, h.spring_n) - 25.0) / ks, 1e-12);
}

TEST(CoulombSlider3d, DashpotWhileSticking) {
    const double ks = 1000.0, cs = 50.0, dt = 1e-3;
    const Vec3 v{0.1, -0.2, 0.0};
    const ShearForce3d f = coulomb_slider_3d(ks, cs, 100.0, v, {}, dt);
    EXPECT_FALSE(f.sliding);
    expect_vec_near(f.dashpot_n, -cs * v, 1e-12);
    expect_vec_near(f.total_n, -ks * dt * v - cs * v, 1e-12);
    // Trapezoid over the interval from a zero dashpot force: 0.5 cs |v|^2 dt.
    EXPECT_NEAR(f.shear_dashpot_work_j, 0.5 * cs * dot(v, v) * dt, 1e-15);
    // The dashpot cannot push the total past the cap.
    const ShearForce3d capped = coulomb_slider_3d(ks, cs, 1.0, v, {}, dt);
    EXPECT_NEAR(length(capped.total_n), 1.0, 1e-12);
}

TEST(CoulombSlider3d, HistoryCarriedIntoATurnedFrame) {
    // The normal turned so that the stored force has a normal part: it is laid back into the new
    // tangent plane with its length kept.
    const ShearHistory3d h{{3.0, 0.0, 4.0}, {0.0, 2.0, 0.0}};
    const ShearHistory3d carried = carry_to_normal(h, {0.0, 0.0, 1.0});
    expect_vec_near(carried.spring_n, {5.0, 0.0, 0.0}, 1e-12);
    expect_vec_near(carried.dashpot_n, {0.0, 2.0, 0.0}, 0.0);
}

}  // namespace
}  // namespace blockdem
