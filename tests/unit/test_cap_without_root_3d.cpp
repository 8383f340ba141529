// The 3-D slider's cap decided from squares (laws/coulomb_slider_3d.hpp: surely_within_below,
// capped_length) against the square-root rule it replaces, bit for bit: vectors whose length is
// the cap to within a few units in the last place, far inside, far outside, zero, and caps whose
// square is subnormal, zero or NaN. And the whole slider against a copy of its square-root form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "laws/coulomb_slider_3d.hpp"

namespace blockdem {
namespace {

// The rule before the squares: |v| by its square root, then the cap.
Vec3 capped_by_root(Vec3 v, double limit) {
    const double l = length(v);
    return l > limit ? (l > 0.0 ? (limit / l) * v : Vec3{}) : v;
}

// The slider before the squares, line for line (three square roots a point).
ShearForce3d slider_by_root(double ks, double cs, double limit, Vec3 velocity, const ShearHistory3d& previous,
                            double dt) {
    ShearForce3d f;
    const Vec3 last = previous.spring_n;
    const Vec3 capped_last = capped_by_root(last, limit);
    const Vec3 increment = dt * velocity;
    const Vec3 trial = capped_last - ks * increment;
    if (length(trial) > limit || !(capped_last == last)) {
        f.sliding = true;
        f.spring_n = capped_by_root(trial, limit);
        f.total_n = f.spring_n;
        const double work = 0.5 * dot(last + f.spring_n, increment);
        const double stored = ks > 0.0 ? 0.5 * (dot(f.spring_n, f.spring_n) - dot(last, last)) / ks : 0.0;
        f.friction_work_j = -work - stored;
    } else {
        f.spring_n = trial;
        f.total_n = capped_by_root(trial - cs * velocity, limit);
        f.dashpot_n = f.total_n - trial;
    }
    f.shear_dashpot_work_j = -0.5 * dot(previous.dashpot_n + f.dashpot_n, increment);
    return f;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(Vec3 a, Vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

// A random direction scaled to the cap, then nudged by a few units in the last place.
Vec3 near_cap(std::mt19937_64& rng, double limit, int nudges) {
    std::normal_distribution<double> gauss;
    Vec3 d{gauss(rng), gauss(rng), gauss(rng)};
    d = (1.0 / length(d)) * d;
    Vec3 v = limit * d;
    for (int k = 0; k < nudges; ++k) v.x = std::nextafter(v.x, nudges % 2 ? 0.0 : 2.0 * v.x);
    return v;
}

TEST(CapWithoutRoot3d, SameVectorAsTheRootAtAndAroundTheCap) {
    std::mt19937_64 rng(15);
    std::uniform_real_distribution<double> exponent(-12.0, 8.0);
    std::uniform_real_distribution<double> factor(0.0, 2.0);
    int decided_without_root = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        const double limit = std::pow(10.0, exponent(rng));
        Vec3 v;
        switch (trial % 4) {
            case 0: v = near_cap(rng, limit, trial % 9); break;           // within units in the last place
            case 1: v = factor(rng) * near_cap(rng, limit, 0); break;     // anywhere from 0 to twice the cap
            case 2: v = (1.0 - 1e-15 * factor(rng)) * near_cap(rng, limit, 0); break;  // at the margin
            default: v = (1.0 + 1e-15 * factor(rng)) * near_cap(rng, limit, 0); break;
        }
        const double below = surely_within_below(limit);
        decided_without_root += dot(v, v) < below;
        ASSERT_TRUE(same_bits(capped_length(v, limit, below), capped_by_root(v, limit)))
            << "limit " << limit << " v " << v.x << " " << v.y << " " << v.z;
    }
    EXPECT_GT(decided_without_root, 50000);  // the shortcut is taken, not only the root
}

TEST(CapWithoutRoot3d, CapsWhoseSquareIsNotANormalNumberTakeTheRoot) {
    const double tiny = 1e-170;  // its square is subnormal: the relative margin would not hold
    const double caps[] = {0.0, tiny, std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::quiet_NaN()};
    for (double limit : caps) {
        EXPECT_EQ(surely_within_below(limit), -1.0) << limit;
        for (Vec3 v : {Vec3{}, Vec3{tiny, 0.0, 0.0}, Vec3{0.5 * tiny, 0.5 * tiny, 0.0}, Vec3{1.0, 2.0, 3.0}})
            EXPECT_TRUE(same_bits(capped_length(v, limit, surely_within_below(limit)), capped_by_root(v, limit)));
    }
}

TEST(CapWithoutRoot3d, SliderIsTheSameBitsAsItsRootForm) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int sliding = 0;
    for (int trial = 0; trial < 100000; ++trial) {
        const double ks = 1e6 * (0.5 + unit(rng)), cs = 1e2 * unit(rng), dt = 1e-4;
        const double limit = trial % 10 == 0 ? 0.0 : 100.0 * unit(rng);
        // Last step's spring near the cap (on it, as after sliding, or just inside or outside).
        const ShearHistory3d previous{near_cap(rng, limit > 0.0 ? limit : 1.0, trial % 5) * (0.9 + 0.2 * unit(rng)),
                                      {gauss(rng), gauss(rng), gauss(rng)}};
        const Vec3 velocity{1e-3 * gauss(rng), 1e-3 * gauss(rng), 1e-3 * gauss(rng)};
        const ShearForce3d a = coulomb_slider_3d(ks, cs, limit, velocity, previous, dt);
        const ShearForce3d b = slider_by_root(ks, cs, limit, velocity, previous, dt);
        sliding += a.sliding;
        ASSERT_EQ(a.sliding, b.sliding);
        ASSERT_TRUE(same_bits(a.spring_n, b.spring_n));
        ASSERT_TRUE(same_bits(a.total_n, b.total_n));
        ASSERT_TRUE(same_bits(a.dashpot_n, b.dashpot_n));
        ASSERT_TRUE(same_bits(a.friction_work_j, b.friction_work_j));
        ASSERT_TRUE(same_bits(a.shear_dashpot_work_j, b.shear_dashpot_work_j));
    }
    EXPECT_GT(sliding, 10000);  // both branches are driven
    EXPECT_LT(sliding, 90000);
}

}  // namespace
}  // namespace blockdem
