// The two-lane doubles of the 3-D law (laws/double_lanes.hpp): each lane must be the scalar
// expression's own result, bit for bit, whatever the other lane holds, since the law's two-point
// line (world/step_3d.cpp) relies on it for a point's result not to depend on its neighbour; and
// lane_max must be std::max's rule, NaN and signed zeros included (the normal force's
// max(0, F) and the cap's max(0, F_n) take it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "laws/double_lanes.hpp"

namespace blockdem {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(DoubleLanes, EachLaneIsTheScalarArithmetic) {
    std::mt19937_64 random(15);
    std::uniform_real_distribution<double> value(-1e3, 1e3);
    const auto vec = [&] { return Vec3{value(random), value(random), value(random)}; };
    for (int i = 0; i < 20000; ++i) {
        const Vec3 a0 = vec(), a1 = vec(), b0 = vec(), b1 = vec();
        const double s0 = value(random), s1 = value(random);
        const Vec3Lanes a = lanes(a0, a1), b = lanes(b0, b1);
        const DoubleLanes s = lanes(s0, s1);
        const DoubleLanes d = dot(a, b);
        const Vec3Lanes c = cross(a, b), t = s * a - b, u = a + b;
        const DoubleLanes root = lane_sqrt(d * d);
        const Vec3 scalar_a[2] = {a0, a1}, scalar_b[2] = {b0, b1};
        const double scalar_s[2] = {s0, s1};
        for (int k = 0; k < 2; ++k) {
            ASSERT_TRUE(same_bits(d[k], blockdem::dot(scalar_a[k], scalar_b[k])));
            const Vec3 ck = blockdem::cross(scalar_a[k], scalar_b[k]);
            const Vec3 tk = scalar_s[k] * scalar_a[k] - scalar_b[k];
            const Vec3 uk = scalar_a[k] + scalar_b[k];
            for (const auto& [lane_value, scalar] : {std::pair{lane(c, k), ck}, std::pair{lane(t, k), tk},
                                                     std::pair{lane(u, k), uk}}) {
                ASSERT_TRUE(same_bits(lane_value.x, scalar.x));
                ASSERT_TRUE(same_bits(lane_value.y, scalar.y));
                ASSERT_TRUE(same_bits(lane_value.z, scalar.z));
            }
            ASSERT_TRUE(same_bits(root[k], std::sqrt(d[k] * d[k])));
        }
    }
}

TEST(DoubleLanes, LaneMaxIsStdMax) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double values[] = {0.0, -0.0, 1.0, -1.0, 1e-310, -1e-310, 1e300, nan,
                             std::numeric_limits<double>::infinity()};
    for (const double a : values)
        for (const double b : values)
            for (const double other : {2.0, nan}) {
                const DoubleLanes m = lane_max(lanes(a, other), lanes(b, -other));
                const double expected = std::max(a, b);
                EXPECT_TRUE(same_bits(m[0], expected) || (std::isnan(m[0]) && std::isnan(expected)))
                    << "max(" << a << ", " << b << ") gave " << m[0];
            }
}

TEST(DoubleLanes, MasksSelectAndBoth) {
    const DoubleLanes x = lanes(1.0, -1.0);
    const LaneMask positive = x > lanes(0.0);
    const DoubleLanes chosen = select(positive, lanes(10.0), lanes(20.0));
    EXPECT_EQ(chosen[0], 10.0);
    EXPECT_EQ(chosen[1], 20.0);
    EXPECT_FALSE(both(positive));
    EXPECT_TRUE(both(x > lanes(-2.0)));
    EXPECT_FALSE(both(x > lanes(2.0)));
    EXPECT_FALSE(both(lanes(std::numeric_limits<double>::quiet_NaN(), 1.0) < lanes(2.0)));
    EXPECT_EQ(lane_sum(lanes(0.25, 0.5)), 0.75);
    const Vec3 sum = lane_sum(lanes(Vec3{1.0, 2.0, 3.0}, Vec3{4.0, 5.0, 6.0}));
    EXPECT_EQ(sum.x, 5.0);
    EXPECT_EQ(sum.y, 7.0);
    EXPECT_EQ(sum.z, 9.0);
}

}  // namespace
}  // namespace blockdem
