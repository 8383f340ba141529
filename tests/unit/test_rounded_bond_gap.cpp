// The rounded narrow phase's gap (geometry/rounded_contact.hpp, gap_m): a bonded joint's points
// are kept, with a negative overlap, while the rounded surfaces are apart by less than the gap,
// as collide_polygons keeps them for sharp corners; beyond the gap the pair is apart.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/polygon.hpp"
#include "geometry/polygon_contact.hpp"
#include "geometry/rounded_contact.hpp"
#include "polygon_test_support.hpp"

namespace blockdem {
namespace {

using testing::box;
using testing::Poly;

constexpr double bond_gap_rounding_m = 0.01;  // r in the comments

TEST(RoundedBondGap, FaceJointOpenWithinTheGapKeepsItsTwoPointsWithTheOpening) {
    const double opening = 2e-4;  // [m] the drawn faces apart by this
    const Poly lower = box(1.0, 0.2, {0.0, -0.1});
    const Poly upper = box(0.5, 0.2, {0.0, 0.1 + opening});
    ContactManifold m;
    AxisCache cache;
    ASSERT_TRUE(collide_rounded(lower.view(), upper.view(), bond_gap_rounding_m, no_reference, m, cache, 3e-4));
    ASSERT_EQ(m.count, 2u);
    for (std::uint32_t k = 0; k < 2; ++k) EXPECT_NEAR(m.points[k].overlap_m, -opening, 1e-15);
    // The points are the ends of the joint's straight part: the upper core's edge, r in from
    // each drawn corner.
    EXPECT_NEAR(std::abs(m.points[0].point_m.x - m.points[1].point_m.x), 0.5 - 2.0 * bond_gap_rounding_m, 1e-12);
    // The next step, through the cache, the same points.
    ContactManifold again;
    ASSERT_TRUE(collide_rounded(lower.view(), upper.view(), bond_gap_rounding_m, m.reference, again, cache, 3e-4));
    ASSERT_EQ(again.count, 2u);
    EXPECT_EQ(again.points[0].overlap_m, m.points[0].overlap_m);
    EXPECT_EQ(again.points[1].point_m.x, m.points[1].point_m.x);
    // Without the gap (no bond), or beyond it, the pair is apart.
    AxisCache fresh;
    EXPECT_FALSE(collide_rounded(lower.view(), upper.view(), bond_gap_rounding_m, no_reference, m, fresh));
    fresh = AxisCache{};
    EXPECT_FALSE(collide_rounded(lower.view(), upper.view(), bond_gap_rounding_m, no_reference, m, fresh, 1e-4));
    // With the cache of a pair in contact, the same answer.
    EXPECT_FALSE(collide_rounded(lower.view(), upper.view(), bond_gap_rounding_m, again.reference, m, cache, 1e-4));
}

TEST(RoundedBondGap, CornerJointOpenWithinTheGapKeepsOnePoint) {
    // Corner to corner along the diagonal: the arcs' centres 2r + opening apart.
    const double opening = 1e-4;
    const double core_half = 0.1 - bond_gap_rounding_m;  // the cores' half width [m]
    const double d = (2.0 * bond_gap_rounding_m + opening) / std::sqrt(2.0);  // the centres' offset along x and y
    const Poly a = box(0.2, 0.2, {0.0, 0.0});
    const Poly b = box(0.2, 0.2, {2.0 * core_half + d, 2.0 * core_half + d});
    ContactManifold m;
    AxisCache cache;
    ASSERT_TRUE(collide_rounded(a.view(), b.view(), bond_gap_rounding_m, no_reference, m, cache, 2e-4));
    ASSERT_EQ(m.count, 1u);
    EXPECT_NEAR(m.points[0].overlap_m, -opening, 1e-12);
    EXPECT_NEAR(m.normal.x, std::sqrt(0.5), 1e-9);
    cache = AxisCache{};
    EXPECT_FALSE(collide_rounded(a.view(), b.view(), bond_gap_rounding_m, no_reference, m, cache, 0.5e-4));
}

}  // namespace
}  // namespace blockdem
