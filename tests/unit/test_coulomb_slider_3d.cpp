// The 3-D shear slider (laws/coulomb_slider_3d.hpp) driven through load, slip, reversal and a
// falling cap against hand-computed forces; and the history carried into a turned contact frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

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


// The carry's length ratio is one root of |v|^2 / (|v|^2 - (v.n)^2) (none where the ratio's
// argument rounds to 1): against the two-length form it replaced, over turns from 1e-12 rad (the
// root skipped) to 1 rad (taken), lengths from 1e-6 to 1e6 N. The result keeps |v| and lies in the
// new plane to a few units of round-off (4e-16 relative: a dot, a square root and a product each
// round once, with |v.n| <= |v|), and differs from the two-length form by no more.
TEST(CoulombSlider3d, CarriedIntoPlaneKeepsTheLengthWithOneRoot) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto random_unit = [&] {
        for (;;) {
            const Vec3 v{unit(random), unit(random), unit(random)};
            if (dot(v, v) > 0.01 && dot(v, v) < 1.0) return (1.0 / length(v)) * v;
        }
    };
    const auto two_lengths = [](Vec3 v, Vec3 n) {
        const Vec3 in_plane = v - dot(v, n) * n;
        const double l = length(in_plane);
        return l > 0.0 ? (length(v) / l) * in_plane : Vec3{};
    };
    int skipped = 0, taken = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 old_normal = random_unit();
        const Vec3 across = random_unit();
        const Vec3 in_old = across - dot(across, old_normal) * old_normal;
        const double magnitude_n = std::pow(10.0, -6.0 + 12.0 * (trial % 13) / 12.0);
        const Vec3 v = (magnitude_n / length(in_old)) * in_old;
        // The new normal: the old one turned by angle about a random axis (Rodrigues).
        const double angle = std::pow(10.0, -12.0 + 12.0 * (trial % 7) / 6.0);
        const Vec3 axis = random_unit();
        const Vec3 turned = std::cos(angle) * old_normal + std::sin(angle) * cross(axis, old_normal) +
                            (1.0 - std::cos(angle)) * dot(axis, old_normal) * axis;
        const Vec3 normal = (1.0 / length(turned)) * turned;
        const Vec3 carried = carried_into_plane(v, normal);
        const double l = length(v);
        ASSERT_NEAR(length(carried), l, 4e-16 * l * 4) << trial;
        ASSERT_LE(std::abs(dot(carried, normal)), 4e-16 * l * 4) << trial;
        const Vec3 before = two_lengths(v, normal);
        ASSERT_LE(length(carried - before), 4e-16 * l * 4) << trial;
        const double along = dot(v, normal);
        (dot(v, v) - along * along == dot(v, v) ? skipped : taken) += 1;
    }
    // Both branches were taken: small turns skip the root, large ones take it.
    EXPECT_GT(skipped, 2000);
    EXPECT_GT(taken, 2000);
}

TEST(CoulombSlider3d, CarriedIntoPlaneDropsAVectorWithNoPartInThePlane) {
    const Vec3 n{0.0, 0.6, 0.8};
    EXPECT_EQ(carried_into_plane(Vec3{}, n), (Vec3{}));
    EXPECT_EQ(carried_into_plane(2.5 * n, n), (Vec3{}));
    // A vector already in the plane exactly (v.n = 0) comes back as it was, bit for bit.
    const Vec3 in_plane{1.0, 0.0, 0.0};
    EXPECT_EQ(carried_into_plane(in_plane, n), in_plane);
}


// The law takes the history through carry_to_normal_for_slider: the spring as carry_to_normal
// lays it (the same bits), last step's dashpot force only scaled. The slider's forces are then the
// same bits, and its dashpot work differs by round-off: at most 8 u |d| |v| dt (v the relative
// velocity, normal part included, whose removal leaves n . increment of a few u |v| dt).
TEST(CoulombSlider3d, TheLawsCarryGivesTheSlidersResultToRoundOff) {
    std::mt19937 random(12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto random_unit = [&] {
        for (;;) {
            const Vec3 v{unit(random), unit(random), unit(random)};
            if (dot(v, v) > 0.01 && dot(v, v) < 1.0) return (1.0 / length(v)) * v;
        }
    };
    const double u = 0x1p-53, dt = 1e-4, ks = 1e6, cs = 300.0;
    double largest = 0.0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 old_normal = random_unit();
        const auto in_old_plane = [&](double size) {
            const Vec3 a = random_unit();
            const Vec3 p = a - dot(a, old_normal) * old_normal;
            return (size / length(p)) * p;
        };
        const ShearHistory3d h{in_old_plane(std::pow(10.0, unit(random) * 3.0)),
                               in_old_plane(std::pow(10.0, unit(random) * 3.0))};
        const double angle = std::pow(10.0, -10.0 + 10.0 * (trial % 6) / 5.0);
        const Vec3 turned = old_normal + angle * cross(random_unit(), old_normal);
        const Vec3 normal = (1.0 / length(turned)) * turned;
        // A relative velocity mostly along the normal (an impact) or across it.
        const Vec3 relative = std::pow(10.0, unit(random) * 2.0) * random_unit() + 10.0 * unit(random) * normal;
        const Vec3 tangential = relative - dot(relative, normal) * normal;
        const double limit = trial % 3 == 0 ? 1e-3 : 1e4;  // sliding and sticking
        const ShearForce3d carried = coulomb_slider_3d(ks, cs, limit, tangential, carry_to_normal(h, normal), dt);
        const ShearForce3d law = coulomb_slider_3d(ks, cs, limit, tangential, carry_to_normal_for_slider(h, normal), dt);
        ASSERT_EQ(law.spring_n, carried.spring_n);
        ASSERT_EQ(law.total_n, carried.total_n);
        ASSERT_EQ(law.sliding, carried.sliding);
        ASSERT_EQ(law.friction_work_j, carried.friction_work_j);
        const double bound = 8.0 * u * (length(h.dashpot_n) + length(law.dashpot_n)) * length(relative) * dt;
        const double difference = std::abs(law.shear_dashpot_work_j - carried.shear_dashpot_work_j);
        ASSERT_LE(difference, bound) << trial;
        largest = std::max(largest, difference / bound);
    }
    EXPECT_GT(largest, 0.0);  // the two forms do differ in their last bits
}

}  // namespace
}  // namespace blockdem
